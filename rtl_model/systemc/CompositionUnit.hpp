// Composition unit: per tap, the nearest of the memories' texels wins.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class CompositionUnit : public PipelineStageModule<cycle::FetchToken, cycle::ComposedToken> {
 public:
  sc_core::sc_port<FifoReadIf<cycle::FetchToken>>& texel_words_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::ComposedToken>>& composed_taps_out = output_;

  SC_HAS_PROCESS(CompositionUnit);
  CompositionUnit(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);

 private:
  void tick(FifoReadIf<cycle::FetchToken>& in, FifoWriteIf<cycle::ComposedToken>& out) override { k_.tick_compose(cycle_, in, out); }
};

}  // namespace arp::scm
