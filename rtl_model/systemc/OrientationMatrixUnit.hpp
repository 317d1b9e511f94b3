// Orientation matrix unit: loads the orientation register at latch points
// and rotates each view vector into the cube frame.
// The module is the generic StageModule over its stage (stage::OrientationStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/OrientationStage.hpp"

namespace arp::scm {

using OrientationMatrixUnit = StageModule<stage::OrientationStage>;

}  // namespace arp::scm
