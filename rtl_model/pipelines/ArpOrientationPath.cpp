#include "ArpOrientationPath.hpp"

#include <cmath>
#include <cstdio>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::pipelines {

ArpOrientationPath::ArpOrientationPath(const DisplayRaster& d, const dp::ArpConfig& c, dp::LatchPolicy latch, double horizon_s)
    : d_(d),
      latch_(latch),
      lead_cycles_(static_cast<int>(dp::PipelineSchedule(c).orientation_lead())),
      horizon_ps_(static_cast<int64_t>(std::llround(horizon_s * 1e12))) {}

std::string ArpOrientationPath::name() const { return "arp-" + dp::to_string(latch_); }

std::string ArpOrientationPath::description() const {
  char b[160];
  std::snprintf(b, sizeof b, "orientation latched per %s at scan-out, %d pixel clocks (%.0f ns) before the photon",
                dp::to_string(latch_).c_str(), lead_cycles_, static_cast<double>(d_.timing().cycles_to_ps(lead_cycles_)) * 1e-3);
  return b;
}

PoseUse ArpOrientationPath::pose_for(int64_t frame, int x, int y) const {
  PoseUse u;
  u.compute_ps = d_.timing().cycles_to_ps(dp::latch_cycle(d_.timing(), latch_, lead_cycles_, frame, 0, x, y));
  u.target_ps = u.compute_ps + horizon_ps_;
  return u;
}

}  // namespace arp::pipelines
