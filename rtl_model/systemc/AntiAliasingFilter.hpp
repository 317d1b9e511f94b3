// Anti-aliasing filter: blends the composited taps (or passes the nearest).
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class AntiAliasingFilter : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::ComposedToken>> composed_taps_in;
  sc_core::sc_port<FifoWriteIf<cycle::ColorToken>> pixel_colors_out;

  SC_HAS_PROCESS(AntiAliasingFilter);
  AntiAliasingFilter(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::ComposedToken>* in_ = nullptr;
  FifoWriteIf<cycle::ColorToken>* out_ = nullptr;
};

}  // namespace arp::scm
