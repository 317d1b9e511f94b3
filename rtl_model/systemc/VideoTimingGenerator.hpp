// Video timing generator: drives the panel's scan position and issues each
// active pixel into the pipeline the schedule's issue lead before its slot.
// The module is the generic StageModule over its stage (stage::VideoTimingStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/VideoTimingStage.hpp"

namespace arp::scm {

using VideoTimingGenerator = StageModule<stage::VideoTimingStage>;

}  // namespace arp::scm
