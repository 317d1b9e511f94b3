#include "FrameError.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arp::host {

HmdFrame area_mean(const HmdFrame& fine, int n) {
  HmdFrame out;
  out.display_bits = fine.display_bits;
  out.frame_index = fine.frame_index;
  out.resize(fine.width / n, fine.height / n, fine.eyes, false);
  const int bits = fine.display_bits;
  const uint32_t nn = static_cast<uint32_t>(n * n);
  for (int e = 0; e < out.eyes; ++e)
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x) {
        uint32_t sum[3] = {0, 0, 0};
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) sum[c] += fine.channel(e, n * x + i, n * y + j, c);
        uint32_t p = 0;
        for (int c = 0; c < 3; ++c) p |= ((2 * sum[c] + nn) / (2 * nn)) << ((2 - c) * bits);
        out.pixels[out.index(e, x, y)] = p;
      }
  return out;
}

ImageError image_error(const HmdFrame& a, const HmdFrame& b) {
  ImageError e;
  if (a.pixels.size() != b.pixels.size() || a.pixels.empty()) return e;
  const int bits = a.display_bits;
  const uint32_t mask = (1u << bits) - 1;
  double sum = 0;
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    bool d = false;
    for (int c = 0; c < 3; ++c) {
      const int sh = (2 - c) * bits;
      const double x = static_cast<double>((a.pixels[i] >> sh) & mask) - static_cast<double>((b.pixels[i] >> sh) & mask);
      sum += x * x;
      d = d || x != 0;
    }
    differ += d ? 1 : 0;
  }
  e.mse = sum / (3.0 * static_cast<double>(a.pixels.size()));
  const double peak = static_cast<double>(mask);
  e.psnr_db = e.mse > 0 ? 10.0 * std::log10(peak * peak / e.mse) : std::numeric_limits<double>::infinity();
  e.differing = static_cast<double>(differ) / static_cast<double>(a.pixels.size());
  return e;
}

double displacement_rad(const glm::dvec3& eye_then, const glm::dvec3& p_then, const glm::dvec3& eye_now,
                        const glm::dvec3& p_now) {
  const glm::dvec3 u = p_then - eye_then, v = p_now - eye_now;
  const double lu = glm::length(u), lv = glm::length(v);
  if (!(lu > 0) || !(lv > 0)) return 0;
  return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
}

}  // namespace arp::host
