// Anti-aliasing filter. Off: the nearest texel (the texel holding the sample
// point). Bilinear: the four texels around the sample point (texel centres at
// i + 1/2, clamp-to-edge within the face -- no filtering across cube edges),
// each tap composited across the memories first, then the four composited
// colours blended with weights from the sub-texel bits. Compositing before
// filtering keeps object edges between memories correct (a filtered depth
// would be meaningless).
#pragma once
#include <algorithm>
#include <cstdint>

#include "DisplayMemoryBank.hpp"

namespace arp::dp {

struct BilinearTaps {
  int32_t x0, x1, y0, y1;
  uint32_t wx, wy;  // weight of x1 / y1, Q0.texel_frac
};

// u, v: texel-space position Q.texel_frac (texel_frac >= 1), in a type I holding them (int32_t for
// positions below 2^31, as the functional model's lines hold them: no step is wider than u).
template <class I>
inline BilinearTaps bilinear_taps_as(I u, I v, int texel_frac, int32_t face_size) {
  const I half = I{1} << (texel_frac - 1);
  const I mask = (I{1} << texel_frac) - 1;
  const I us = u - half, vs = v - half;
  const int32_t i0 = static_cast<int32_t>(us >> texel_frac), j0 = static_cast<int32_t>(vs >> texel_frac);
  auto clampi = [face_size](int32_t i) { return i < 0 ? 0 : (i >= face_size ? face_size - 1 : i); };
  return {clampi(i0), clampi(i0 + 1), clampi(j0), clampi(j0 + 1), static_cast<uint32_t>(us & mask),
          static_cast<uint32_t>(vs & mask)};
}
inline BilinearTaps bilinear_taps(int64_t u, int64_t v, int texel_frac, int32_t face_size) {
  return bilinear_taps_as<int64_t>(u, v, texel_frac, face_size);
}

struct ChannelLayout {
  int shift[3];
  uint32_t mask[3];
  explicit ChannelLayout(const MemoryFormat& f)
      : shift{f.green_bits + f.blue_bits, f.blue_bits, 0},
        mask{(1u << f.red_bits) - 1, (1u << f.green_bits) - 1, (1u << f.blue_bits) - 1} {}
};

// The same layout fixed at compile time (R, G, B bits): a caller that has checked its format is
// this one (same()) gets immediate shifts and masks.
template <int R, int G, int B>
struct FixedChannelLayout {
  static constexpr int shift[3] = {G + B, B, 0};
  static constexpr uint32_t mask[3] = {(1u << R) - 1, (1u << G) - 1, (1u << B) - 1};
  static bool same(const ChannelLayout& L) {
    for (int c = 0; c < 3; ++c)
      if (L.shift[c] != shift[c] || L.mask[c] != mask[c]) return false;
    return true;
  }
};

// Per channel: ((c00(W-wx) + c10 wx)(W-wy) + (c01(W-wx) + c11 wx) wy) / W^2,
// rounded half up; W = 2^texel_frac. The sum is at most mask W^2 + W^2/2: 16-bit
// channels and 16 weight bits fit the 64-bit accumulator, so bilinear_blend always
// holds it. Acc = uint32_t computes the same value where blend_fits_32 says the
// sum fits 32 bits (8-bit channels up to texel_frac 12); a vector unit then takes
// twice the pixels at once.
template <class Acc, class Layout = ChannelLayout>
inline uint32_t bilinear_blend_in(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t wx, uint32_t wy,
                                  int texel_frac, const Layout& L) {
  const Acc W = Acc{1} << texel_frac;
  const int shift = 2 * texel_frac;
  const Acc round = Acc{1} << (shift - 1);
  uint32_t out = 0;
  for (int c = 0; c < 3; ++c) {
    const Acc a = (c00 >> L.shift[c]) & L.mask[c], b = (c10 >> L.shift[c]) & L.mask[c];
    const Acc d = (c01 >> L.shift[c]) & L.mask[c], e = (c11 >> L.shift[c]) & L.mask[c];
    const Acc top = a * (W - wx) + b * wx, bottom = d * (W - wx) + e * wx;
    const Acc v = (top * (W - wy) + bottom * wy + round) >> shift;
    out |= static_cast<uint32_t>(v) << L.shift[c];
  }
  return out;
}

inline uint32_t bilinear_blend(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t wx, uint32_t wy,
                               int texel_frac, const ChannelLayout& L) {
  return bilinear_blend_in<uint64_t>(c00, c10, c01, c11, wx, wy, texel_frac, L);
}

// Whether the largest sum, mask W^2 + W^2/2 over the widest channel, fits 32 bits.
inline bool blend_fits_32(int texel_frac, const ChannelLayout& L) {
  const uint64_t m = std::max({L.mask[0], L.mask[1], L.mask[2]});
  const uint64_t W2 = uint64_t{1} << (2 * texel_frac);
  return m * W2 + W2 / 2 <= UINT32_MAX;
}

}  // namespace arp::dp
