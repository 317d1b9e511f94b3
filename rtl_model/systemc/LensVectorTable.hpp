// Lens vector table: the ROM of head-frame viewing directions, read for each issued pixel
// (stage::LensVectorStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/LensVectorStage.hpp"

namespace arp::scm {

class LensVectorTable : public StageModule<stage::LensVectorStage> {
 public:
  static constexpr const char* kInput = "pixel_requests", *kOutput = "view_vectors";
  static constexpr const char* kInstance = "lens_vector_table";
  sc_core::sc_port<FifoReadIf<stage::PixelSlot>>& pixel_requests_in = input;
  sc_core::sc_port<FifoWriteIf<stage::LensToken>>& view_vectors_out = output;

  LensVectorTable(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : StageModule(name, ctx, kInput, kOutput, {"view_x", "view_y", "view_z"}) {}
};

}  // namespace arp::scm
