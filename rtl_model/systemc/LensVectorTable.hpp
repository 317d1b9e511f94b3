// Lens vector table: the ROM of head-frame viewing directions, read for each issued pixel.
// The module is the generic StageModule over its stage (stage::LensVectorStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/LensVectorStage.hpp"

namespace arp::scm {

using LensVectorTable = StageModule<stage::LensVectorStage>;

}  // namespace arp::scm
