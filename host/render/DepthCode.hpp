// Depth in display memory: the distance from the eye (radial, so the codes of
// different faces and of memories rendered from nearby positions compare
// sensibly in the composition unit), quantised logarithmically between a near
// and a far distance into codes 0 .. 2^D - 2 (2^D - 1 is "empty"). A
// logarithmic scale keeps the relative depth resolution constant:
// 16 bits over 0.05 .. 1000 m resolve about 0.015 % of the distance.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace arp::host {

struct DepthCode {
  double near_m = 0.05, far_m = 1000.0;
  int bits = 16;
  uint32_t max_code() const { return static_cast<uint32_t>((uint64_t{1} << bits) - 2); }
  uint32_t code(double distance_m) const { return code(distance_m, log_range()); }
  // The same with log(far / near) given (a loop over many texels takes it once).
  double log_range() const { return std::log(far_m / near_m); }
  uint32_t code(double distance_m, double log_range) const {
    const double t = std::log(std::max(distance_m, near_m) / near_m) / log_range;
    const double c = std::nearbyint(std::min(t, 1.0) * max_code());
    return static_cast<uint32_t>(c);
  }
  // code() of n distances at once, the same codes (+infinity gives max_code(); a distance is never NaN): a
  // series logarithm that vectorises, and code() itself wherever the series' value of the code before
  // rounding lies within kTieMargin of a rounding boundary, or always when the format would let the
  // series' error (bounded by 1e-13 (L + 1) on the logarithm, L = log(far / near); about 3e-16 measured)
  // reach a thousandth of that margin.
  void codes(const double* distance_m, uint32_t* out, size_t n) const;
  static constexpr double kTieMargin = 1e-3;
  // At 1 bit every distance is code 0 (the code only marks a texel written): it stands for the near distance.
  double distance(uint32_t c) const {
    if (max_code() == 0) return near_m;
    return near_m * std::exp(static_cast<double>(c) / max_code() * std::log(far_m / near_m));
  }
};

}  // namespace arp::host
