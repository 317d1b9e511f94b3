// Composition unit: per tap, the nearest of the memories' texels wins.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class CompositionUnit : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::FetchToken>> texel_words_in;
  sc_core::sc_port<FifoWriteIf<cycle::ComposedToken>> composed_taps_out;

  SC_HAS_PROCESS(CompositionUnit);
  CompositionUnit(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::FetchToken>* in_ = nullptr;
  FifoWriteIf<cycle::ComposedToken>* out_ = nullptr;
};

}  // namespace arp::scm
