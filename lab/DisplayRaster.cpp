#include "DisplayRaster.hpp"

#include <cmath>

namespace arp::lab {

dp::VideoTimingConfig ntsc_like_timing() {
  // 780 clocks per line, 525 lines, 780 x 525 x 29.97 Hz; interlaced.
  dp::VideoTimingConfig t = dp::VideoTimingConfig::mode(1, {600, 20, 60, 100}, {480, 14, 6, 25}, 12'272'727);
  t.fields_per_frame = 2;
  return t;
}

DisplayRaster::DisplayRaster(const dp::VideoTimingConfig& timing, double fov_deg)
    : t_(timing), fov_deg_(fov_deg), focal_px_(0.5 * timing.h_active / std::tan(0.5 * glm::radians(fov_deg))) {
  const int64_t blank_lines = (timing.v_total() - timing.v_active) / timing.fields_per_frame;
  vblank_ps_ = t_.cycles_to_ps(blank_lines * timing.h_total());
}

int64_t DisplayRaster::photon_ps(int64_t frame, int x, int y) const { return t_.cycles_to_ps(t_.pixel_cycle(frame, 0, x, y)); }

int64_t DisplayRaster::field_start_ps(int64_t frame, int field) const {
  return t_.cycles_to_ps(t_.field_start_cycle(frame, field));
}

int64_t DisplayRaster::line_period_ps() const { return t_.cycles_to_ps(t_.config().h_total()); }

int64_t DisplayRaster::first_field_swapped_after(int64_t t_ps) const {
  // Field k's blank starts at field_start(k) - vblank; fields are nearly
  // periodic (exact edges), so estimate and step.
  const int64_t period = field_period_ps();
  int64_t k = std::max<int64_t>(0, (t_ps + vblank_ps_) / period - 1);
  while (field_start_ps(k) - vblank_ps_ < t_ps) ++k;
  while (k > 0 && field_start_ps(k - 1) - vblank_ps_ >= t_ps) --k;
  return k;
}

int64_t DisplayRaster::frame_at(int64_t t_ps) const {
  if (t_ps < 0) return -1;
  int64_t f = t_ps / std::max<int64_t>(1, t_.cycles_to_ps(t_.frame_cycles()));
  while (field_start_ps(f + 1, 0) <= t_ps) ++f;
  while (f > 0 && field_start_ps(f, 0) > t_ps) --f;
  return f;
}

glm::dvec3 DisplayRaster::ray(double x, double y) const {
  return glm::normalize(glm::dvec3(x + 0.5 - 0.5 * width(), 0.5 * height() - (y + 0.5), -focal_px_));
}

}  // namespace arp::lab
