#include "ArpOrientationPath.hpp"

#include <cmath>
#include <cstdio>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "common/Units.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"

namespace arp::lab {

ArpOrientationPath::ArpOrientationPath(const DisplayRaster& d, const dp::ArpConfig& c, dp::LatchPolicy latch, double horizon_s,
                                       const ArpTranslation& translation)
    : d_(d),
      latch_(latch),
      rule_(d.timing(), latch, dp::PipelineSchedule(c).orientation_lead()),
      horizon_ps_(static_cast<int64_t>(std::llround(horizon_s * 1e12))),
      tr_(translation) {
  if (tr_.threshold_rad <= 0) tr_.threshold_rad = dp::texel_angle_rad(c.memory.face_size);
}

void ArpOrientationPath::schedule(int64_t first_frame, int64_t last_frame) {
  first_ = first_frame;
  renders_ = 0;
  position_ps_.clear();
  if (!tr_.feed || !tr_.feed->has_positions()) return;
  const double threshold_m = tr_.point_distance_m * std::sqrt(2.0 * (1.0 - std::cos(tr_.threshold_rad)));
  // Decided at the blank before frame k - 1 (rendered during it), shown from frame k.
  auto decision_ps = [&](int64_t k) { return d_.field_start_ps(k - 1, 0) - d_.vblank_ps(); };
  int64_t from = tr_.feed->report_sample_ps(decision_ps(first_frame - 1));
  for (int64_t k = first_frame; k <= last_frame; ++k) {
    const int64_t latest = tr_.feed->report_sample_ps(decision_ps(k));
    if (glm::length(tr_.feed->truth_position(latest) - tr_.feed->truth_position(from)) > threshold_m) {
      from = latest;
      ++renders_;
    }
    position_ps_.push_back(from);
  }
}

std::string ArpOrientationPath::name() const { return "arp-" + dp::to_string(latch_); }

std::string ArpOrientationPath::description() const {
  char b[200];
  std::snprintf(b, sizeof b, "orientation latched per %s at scan-out, %d pixel clocks (%.0f ns) before the photon",
                dp::to_string(latch_).c_str(), static_cast<int>(rule_.lead_cycles()),
                static_cast<double>(d_.timing().cycles_to_ps(rule_.lead_cycles())) * 1e-3);
  std::string out = b;
  if (tr_.feed && tr_.feed->has_positions()) {
    std::snprintf(b, sizeof b, "; translation by priority rendering (theta_t %.2f deg at %.1f m, %lld re-renders)",
                  rad_to_deg(tr_.threshold_rad), tr_.point_distance_m, static_cast<long long>(renders_));
    out += b;
  }
  return out;
}

PoseUse ArpOrientationPath::pose_for(int64_t frame, int x, int y) const {
  PoseUse u;
  u.compute_ps = d_.timing().cycles_to_ps(rule_.read_cycle(frame, 0, x, y));
  u.target_ps = u.compute_ps + horizon_ps_;
  if (!position_ps_.empty() && frame >= first_ && frame - first_ < static_cast<int64_t>(position_ps_.size()))
    u.position_ps = position_ps_[static_cast<size_t>(frame - first_)];
  return u;
}

}  // namespace arp::lab
