// Composition unit: per tap, the nearest of the memories' texels wins (stage::CompositionStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/CompositionStage.hpp"

namespace arp::scm {

class CompositionUnit : public StageModule<stage::CompositionStage> {
 public:
  static constexpr const char* kInput = "texel_words", *kOutput = "composed_taps";
  static constexpr const char* kInstance = "composition_unit";
  sc_core::sc_port<FifoReadIf<stage::FetchToken>>& texel_words_in = input;
  sc_core::sc_port<FifoWriteIf<stage::ComposedToken>>& composed_taps_out = output;

  CompositionUnit(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : StageModule(name, ctx, kInput, kOutput, {"color_tap0", "color_tap1", "weight_x"}) {}
};

}  // namespace arp::scm
