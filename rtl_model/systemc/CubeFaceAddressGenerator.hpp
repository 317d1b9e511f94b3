// Cube-face address generator: face, texel and sub-texel bits of each rotated vector.
// The module is the generic StageModule over its stage (stage::AddressStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/AddressStage.hpp"

namespace arp::scm {

using CubeFaceAddressGenerator = StageModule<stage::AddressStage>;

}  // namespace arp::scm
