// Composition unit: per tap, the nearest of the memories' texels wins (depth
// compare; ties to the lower memory; all empty shows the background);
// timed.compose_latency clocks.
#pragma once
#include "RegisteredStage.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"

namespace arp::stage {

class CompositionStage : public RegisteredStage<FetchToken, ComposedToken> {
 public:
  static constexpr dp::Stage kId = dp::Stage::Compose;
  explicit CompositionStage(const StageContext& ctx)
      : RegisteredStage(ctx, kId),
        comp_(dp::MemoryFormat(ctx.config().memory), ctx.config().memory.background),
        memories_(ctx.config().memory.count),
        taps_(ctx.config().pipeline.aa == dp::AaMode::Bilinear ? 4 : 1) {}

  template <class InFifo, class OutFifo>
  void tick(int64_t cycle, InFifo& in, OutFifo& out) {
    tick_with(cycle, in, out, [this](const FetchToken& t, ComposedToken& o) { compute(t, o); });
  }
  void compute(const FetchToken& in, ComposedToken& t) const {
    t.slot = in.slot;
    t.sample = in.sample;
    for (int k = 0; k < in.slot.eye_count; ++k) {
      t.wx[k] = in.wx[k];
      t.wy[k] = in.wy[k];
      for (int i = 0; i < taps_; ++i) t.tap_color[k][i] = dp::compose(in.words[k][i], memories_, comp_).color;
    }
  }

 private:
  dp::CompositionParams comp_;
  int memories_, taps_;
};

}  // namespace arp::stage
