// HMD scan-out: takes each slot's pixel from its FIFO, converts it to the
// panel's colour depth and shows it at the slot; counts underflows
// (stage::ScanOutStage). The last module of the chain: it has no output.
#pragma once
#include <systemc>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/ScanOutStage.hpp"

namespace arp::scm {

class HmdScanOut : public sc_core::sc_module {
 public:
  using Stage = stage::ScanOutStage;
  using Input = stage::ColorToken;
  using Output = void;
  static constexpr const char* kInput = "pixel_colors";
  static constexpr const char* kInstance = "hmd_scan_out";
  sc_core::sc_port<ClockIf> clk;
  sc_core::sc_port<FifoReadIf<stage::ColorToken>> pixel_colors_in;
  sc_core::sc_port<FifoReadIf<stage::ColorToken>>& input = pixel_colors_in;

  SC_HAS_PROCESS(HmdScanOut);
  HmdScanOut(sc_core::sc_module_name name, const stage::StageContext& ctx);
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) {
    return {c.timed.stage[static_cast<size_t>(dp::Stage::ScanOut)].latency_cycles, static_cast<int>(dp::Stage::ScanOut)};
  }
  stage::ScanOutStage& stage() { return stage_; }
  const stage::ScanOutStage& stage() const { return stage_; }
  void trace(sc_core::sc_trace_file* tf) const;
  void stop_trace() {}

 private:
  void end_of_elaboration() override { in_ = pixel_colors_in.operator->(); }
  void on_clock() { stage_.tick(clk->cycle(), *in_); }
  stage::ScanOutStage stage_;
  FifoReadIf<stage::ColorToken>* in_ = nullptr;
};

}  // namespace arp::scm
