#include "LensVectorTable.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "common/Units.hpp"

namespace arp::dp {

double LensVectorTable::lens_center_x(const LensConfig& lens, const VideoTimingConfig& timing, int eye) {
  // The nose is to the right of the left eye (eye 0) and to the left of the right eye.
  const double toward_nose = timing.eyes == 2 ? (eye == 0 ? 1.0 : -1.0) : 0.0;
  return timing.h_active / 2.0 + toward_nose * lens.center_offset_px;
}

LensVectorTable::LensVectorTable(const LensConfig& lens, const VideoTimingConfig& timing, int vec_frac)
    : w_(timing.h_active), h_(timing.v_active), eyes_(timing.eyes), frac_(vec_frac) {
  const size_t n = static_cast<size_t>(eyes_) * w_ * h_;
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  const double half_w = w_ / 2.0;
  const double tan_half = std::tan(lens.fov_deg * kPi / 360.0);
  const int bits = vec_frac + 2;
  for (int e = 0; e < eyes_; ++e) {
    const double cx = lens_center_x(lens, timing, e);
    for (int py = 0; py < h_; ++py) {
      for (int px = 0; px < w_; ++px) {
        const double nx = (px + 0.5 - cx) / half_w;
        const double ny = (py + 0.5 - h_ / 2.0) / half_w;
        const double r2 = nx * nx + ny * ny;
        const double s = lens.k[0] + r2 * (lens.k[1] + r2 * (lens.k[2] + r2 * lens.k[3]));
        const double dx = nx * s * tan_half, dy = -ny * s * tan_half, dz = -1.0;
        const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
        const size_t i = index(e, px, py);
        x_[i] = static_cast<int32_t>(quantise_real(dx * inv, vec_frac, bits));
        y_[i] = static_cast<int32_t>(quantise_real(dy * inv, vec_frac, bits));
        z_[i] = static_cast<int32_t>(quantise_real(dz * inv, vec_frac, bits));
        for (const int32_t c : {x_[i], y_[i], z_[i]}) max_abs_ = std::max(max_abs_, std::abs(int64_t{c}));
      }
    }
  }
}

}  // namespace arp::dp
