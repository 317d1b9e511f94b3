#include "FaceWords.hpp"

#include <algorithm>
#include <cmath>

#include "common/VectorClones.hpp"

namespace arp::host {
namespace {

// std::lround of a channel value 0 .. 255 (halves away from zero), without the library call: c - r is
// exact for 0 <= r <= c < r + 1. A NaN (never produced) reads as 0.
inline int round_channel(double c) {
  const double v = c >= 0.0 ? c : 0.0;
  const int r = static_cast<int>(v);
  return r + (v - r >= 0.5 ? 1 : 0);
}

ARP_VECTOR_CLONES
void pack_texels(const double* distance, const glm::dvec3* color, const uint32_t* code, size_t m, const dp::Rgb8Packer& pack,
                 uint64_t empty, uint64_t* __restrict out) {
  for (size_t k = 0; k < m; ++k) {
    const glm::dvec3 c = glm::clamp(color[k], 0.0, 1.0) * 255.0;
    const uint64_t word = (uint64_t{code[k]} << 32) | pack(static_cast<uint8_t>(round_channel(c.r)), static_cast<uint8_t>(round_channel(c.g)),
                                                          static_cast<uint8_t>(round_channel(c.b)));
    out[k] = std::isfinite(distance[k]) ? word : empty;
  }
}

}  // namespace

void face_words(const double* distance, const glm::dvec3* color, size_t n, const DepthCode& depth, const dp::Rgb8Packer& pack,
                uint64_t empty, uint64_t* out) {
  constexpr size_t kChunk = 256;  // the codes of a chunk stay in L1 between the two passes
  uint32_t code[kChunk];
  for (size_t base = 0; base < n; base += kChunk) {
    const size_t m = std::min(kChunk, n - base);
    depth.codes(distance + base, code, m);
    pack_texels(distance + base, color + base, code, m, pack, empty, out + base);
  }
}

}  // namespace arp::host
