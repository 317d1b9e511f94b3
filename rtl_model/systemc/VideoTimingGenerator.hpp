// Video timing generator: drives the panel's scan position and issues each
// active pixel into the pipeline PipelineSchedule::issue_lead() clocks before
// its slot (cycle::ScanTiming).
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class VideoTimingGenerator : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoWriteIf<cycle::PixelSlot>> pixel_requests_out;

  SC_HAS_PROCESS(VideoTimingGenerator);
  VideoTimingGenerator(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoWriteIf<cycle::PixelSlot>* out_ = nullptr;
};

}  // namespace arp::scm
