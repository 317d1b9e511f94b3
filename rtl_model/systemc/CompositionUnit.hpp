// Composition unit: per tap, the nearest of the memories' texels wins.
// The module is the generic StageModule over its stage (stage::CompositionStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/CompositionStage.hpp"

namespace arp::scm {

using CompositionUnit = StageModule<stage::CompositionStage>;

}  // namespace arp::scm
