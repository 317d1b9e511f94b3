// Anti-aliasing filter: blends the composited taps (or passes the nearest).
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class AntiAliasingFilter : public PipelineStageModule<cycle::ComposedToken, cycle::ColorToken> {
 public:
  sc_core::sc_port<FifoReadIf<cycle::ComposedToken>>& composed_taps_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::ColorToken>>& pixel_colors_out = output_;

  SC_HAS_PROCESS(AntiAliasingFilter);
  AntiAliasingFilter(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);

 private:
  void tick(FifoReadIf<cycle::ComposedToken>& in, FifoWriteIf<cycle::ColorToken>& out) override { k_.tick_filter(cycle_, in, out); }
};

}  // namespace arp::scm
