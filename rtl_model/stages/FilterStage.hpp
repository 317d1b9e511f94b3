// Anti-aliasing filter: the four composited taps blended with the sub-texel
// weights (rounded half up), or the nearest tap when off; timed.filter_latency clocks.
#pragma once
#include "RegisteredStage.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"

namespace arp::stage {

class FilterStage : public RegisteredStage<FilterStage, ComposedToken, ColorToken, kFilterInfo> {
 public:
  explicit FilterStage(const StageContext& ctx)
      : RegisteredStage(ctx),
        layout_(dp::MemoryFormat(ctx.config().memory)),
        texel_frac_(ctx.config().widths.texel_frac),
        bilinear_(ctx.config().pipeline.aa == dp::AaMode::Bilinear) {}

  void compute(const ComposedToken& in, ColorToken& t) const {
    for_each_eye(in, t, [&](int k) {
      const uint32_t* c = in.tap_color[k];
      t.color[k] = bilinear_ ? dp::bilinear_blend(c[0], c[1], c[2], c[3], in.wx[k], in.wy[k], texel_frac_, layout_) : c[0];
    });
  }

 private:
  dp::ChannelLayout layout_;
  int texel_frac_;
  bool bilinear_;
};

}  // namespace arp::stage
