// HMD scan-out: takes each slot's pixel from its FIFO, converts it to the
// panel's colour depth and shows it at the slot; counts underflows
// (cycle::ScanOutStage).
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class HmdScanOut : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::ColorToken>> pixel_colors_in;

  SC_HAS_PROCESS(HmdScanOut);
  HmdScanOut(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::ColorToken>* in_ = nullptr;
};

}  // namespace arp::scm
