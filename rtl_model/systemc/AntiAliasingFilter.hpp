// Anti-aliasing filter: blends the composited taps, or passes the nearest (stage::FilterStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/FilterStage.hpp"

namespace arp::scm {

class AntiAliasingFilter : public StageModule<stage::FilterStage> {
 public:
  static constexpr const char* kInput = "composed_taps", *kOutput = "pixel_colors";
  static constexpr const char* kInstance = "anti_aliasing_filter";
  sc_core::sc_port<FifoReadIf<stage::ComposedToken>>& composed_taps_in = input;
  sc_core::sc_port<FifoWriteIf<stage::ColorToken>>& pixel_colors_out = output;

  AntiAliasingFilter(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : StageModule(name, ctx, kInput, kOutput, {"color", "x", "y"}) {}
};

}  // namespace arp::scm
