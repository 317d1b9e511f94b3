// HMD scan-out: takes each slot's pixel from its FIFO, converts it to the
// panel's colour depth and shows it at the slot; counts underflows.
// The module is the generic StageModule over its stage (stage::ScanOutStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/ScanOutStage.hpp"

namespace arp::scm {

using HmdScanOut = StageModule<stage::ScanOutStage>;

}  // namespace arp::scm
