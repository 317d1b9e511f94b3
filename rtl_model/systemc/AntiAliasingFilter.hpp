// Anti-aliasing filter: blends the composited taps, or passes the nearest.
// The module is the generic StageModule over its stage (stage::FilterStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/FilterStage.hpp"

namespace arp::scm {

using AntiAliasingFilter = StageModule<stage::FilterStage>;

}  // namespace arp::scm
