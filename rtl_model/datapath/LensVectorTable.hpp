// Lens vector table: the ROM holding, for every active pixel of each eye, the
// lens-corrected unit viewing direction in the head frame (x right, y up,
// looking down -z), as signed Q1.vec_frac. Built once from the lens model;
// stored structure-of-arrays so a scanline streams through it.
#pragma once
#include <cstdint>
#include <vector>

#include "ArpConfig.hpp"

namespace arp::dp {

struct Vec3q {
  int32_t x, y, z;
};

class LensVectorTable {
 public:
  LensVectorTable(const LensConfig& lens, const VideoTimingConfig& timing, int vec_frac);

  int width() const { return w_; }
  int height() const { return h_; }
  int eyes() const { return eyes_; }
  int vec_frac() const { return frac_; }

  Vec3q at(int eye, int x, int y) const {
    const size_t i = index(eye, x, y);
    return {x_[i], y_[i], z_[i]};
  }
  // Row pointers for streaming a scanline.
  const int32_t* row_x(int eye, int y) const { return x_.data() + index(eye, 0, y); }
  const int32_t* row_y(int eye, int y) const { return y_.data() + index(eye, 0, y); }
  const int32_t* row_z(int eye, int y) const { return z_.data() + index(eye, 0, y); }

  // The largest magnitude of any component in the table (the orientation unit's narrow-loop bound).
  int64_t max_abs_component() const { return max_abs_; }

  // Horizontal position of eye e's lens centre, in pixels from the left edge.
  static double lens_center_x(const LensConfig& lens, const VideoTimingConfig& timing, int eye);

 private:
  size_t index(int eye, int x, int y) const {
    return (static_cast<size_t>(eye) * h_ + static_cast<size_t>(y)) * w_ + static_cast<size_t>(x);
  }
  int w_, h_, eyes_, frac_;
  int64_t max_abs_ = 0;
  std::vector<int32_t> x_, y_, z_;
};

}  // namespace arp::dp
