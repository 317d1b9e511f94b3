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
    if (!bilinear_) return for_each_eye(in, t, [&](int k) { t.color[k] = in.tap_color[k][0]; });
    if (rgb888_) return blend(in, t, Rgb888{});
    blend(in, t, layout_);
  }

 private:
  using Rgb888 = dp::FixedChannelLayout<8, 8, 8>;  // the default format's: immediate shifts and masks
  template <class Layout>
  void blend(const ComposedToken& in, ColorToken& t, const Layout& L) const {
    for_each_eye(in, t, [&](int k) {
      const uint32_t* c = in.tap_color[k];
      t.color[k] = dp::bilinear_blend_in<uint64_t>(c[0], c[1], c[2], c[3], in.wx[k], in.wy[k], texel_frac_, L);
    });
  }

  dp::ChannelLayout layout_;
  int texel_frac_;
  bool bilinear_;
  bool rgb888_ = Rgb888::same(layout_);
};

}  // namespace arp::stage
