// Cube-face address generator: face, texel and sub-texel bits of each rotated vector
// (stage::AddressStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/AddressStage.hpp"

namespace arp::scm {

class CubeFaceAddressGenerator : public StageModule<stage::AddressStage> {
 public:
  static constexpr const char* kInput = "world_vectors", *kOutput = "cube_addresses";
  static constexpr const char* kInstance = "cube_face_address_generator";
  sc_core::sc_port<FifoReadIf<stage::RotatedToken>>& world_vectors_in = input;
  sc_core::sc_port<FifoWriteIf<stage::AddressToken>>& cube_addresses_out = output;

  CubeFaceAddressGenerator(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : StageModule(name, ctx, kInput, kOutput, {"face", "texel_x", "texel_y"}) {}
};

}  // namespace arp::scm
