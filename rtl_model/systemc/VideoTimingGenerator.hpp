// Video timing generator: drives the panel's scan position and issues each
// active pixel into the pipeline the schedule's issue lead before its slot
// (stage::VideoTimingStage). The first module of the chain: it has no input.
#pragma once
#include <systemc>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/VideoTimingStage.hpp"

namespace arp::scm {

class VideoTimingGenerator : public sc_core::sc_module {
 public:
  using Stage = stage::VideoTimingStage;
  using Input = void;
  using Output = stage::PixelSlot;
  static constexpr const char* kOutput = "pixel_requests";
  static constexpr const char* kInstance = "video_timing_generator";
  sc_core::sc_port<ClockIf> clk;
  sc_core::sc_port<FifoWriteIf<stage::PixelSlot>> pixel_requests_out;
  sc_core::sc_port<FifoWriteIf<stage::PixelSlot>>& output = pixel_requests_out;

  SC_HAS_PROCESS(VideoTimingGenerator);
  VideoTimingGenerator(sc_core::sc_module_name name, const stage::StageContext& ctx);
  stage::VideoTimingStage& stage() { return stage_; }
  const stage::VideoTimingStage& stage() const { return stage_; }
  void trace(sc_core::sc_trace_file* tf);
  void stop_trace() { stage_.track_position = false; }

 private:
  void end_of_elaboration() override { out_ = pixel_requests_out.operator->(); }
  void on_clock() { stage_.tick(clk->cycle(), *out_); }
  stage::VideoTimingStage stage_;
  FifoWriteIf<stage::PixelSlot>* out_ = nullptr;
};

}  // namespace arp::scm
