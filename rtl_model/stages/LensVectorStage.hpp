// Lens vector table: the ROM of head-frame viewing directions (signed
// Q1.vec_frac), read for each issued pixel; timed.lens_latency clocks.
#pragma once
#include "RegisteredStage.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"

namespace arp::stage {

class LensVectorStage : public RegisteredStage<LensVectorStage, PixelSlot, LensToken, kLensVectorInfo> {
 public:
  explicit LensVectorStage(const StageContext& ctx)
      : RegisteredStage(ctx), table_(ctx.config().lens, ctx.config().timing, ctx.config().widths.vec_frac) {}

  void compute(const PixelSlot& s, LensToken& t) const {
    t.slot = s;
    for (int k = 0; k < s.eye_count; ++k) t.view[k] = table_.at(s.eye_first + k, s.x, s.y);
  }
  const dp::LensVectorTable& table() const { return table_; }

 private:
  dp::LensVectorTable table_;
};

}  // namespace arp::stage
