// Composition unit: per tap, the nearest of the memories' texels wins (depth
// compare; ties to the lower memory; all empty shows the background);
// timed.compose_latency clocks.
#pragma once
#include "RegisteredStage.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"

namespace arp::stage {

class CompositionStage : public RegisteredStage<CompositionStage, FetchToken, ComposedToken, kCompositionInfo> {
 public:
  explicit CompositionStage(const StageContext& ctx)
      : RegisteredStage(ctx),
        comp_(dp::MemoryFormat(ctx.config().memory), ctx.config().memory.background),
        memories_(ctx.config().memory.count),
        taps_(ctx.config().pipeline.aa == dp::AaMode::Bilinear ? 4 : 1) {}

  void compute(const FetchToken& in, ComposedToken& t) const {
    static_assert(dp::kCompositionInputs == 8, "one case per memory count");
    switch (memories_) {  // the count as a constant: compose's compares unrolled into selects
      case 1: return compose_taps<1>(in, t);
      case 2: return compose_taps<2>(in, t);
      case 3: return compose_taps<3>(in, t);
      case 4: return compose_taps<4>(in, t);
      case 5: return compose_taps<5>(in, t);
      case 6: return compose_taps<6>(in, t);
      case 7: return compose_taps<7>(in, t);
      default: return compose_taps<8>(in, t);
    }
  }

 private:
  // Every memory read: the compares unrolled. Some faces never written (the memory read left them
  // out): only the memories held, the same composite.
  template <int N>
  void compose_taps(const FetchToken& in, ComposedToken& t) const {
    constexpr uint32_t kAll = (1u << N) - 1;
    for_each_eye(in, t, [&](int k) {
      t.wx[k] = in.wx[k];
      t.wy[k] = in.wy[k];
      const uint32_t held = in.held[k] & kAll;
      if (held == kAll) {
        for (int i = 0; i < taps_; ++i) t.tap_color[k][i] = dp::compose(in.words[k][i], N, comp_).color;
      } else if (held == 1) {  // the one memory drawn on, most often: no compares
        for (int i = 0; i < taps_; ++i) t.tap_color[k][i] = dp::compose(in.words[k][i], 1, comp_).color;
      } else {
        for (int i = 0; i < taps_; ++i) t.tap_color[k][i] = dp::compose_held(in.words[k][i], held, comp_).color;
      }
    });
  }

  dp::CompositionParams comp_;
  int memories_, taps_;
};

}  // namespace arp::stage
