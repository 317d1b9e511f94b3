// The software renderer's store: DepthCode::codes (a series logarithm, vectorised) against code() (the
// library logarithm) texel by texel, above all where the code before rounding lies at a rounding boundary;
// face_words against lround and pack_rgb8 per channel.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "host/render/DepthCode.hpp"
#include "host/render/FaceWords.hpp"

using namespace arp;

namespace {

// Distances log-uniform over [near / 2, 2 far], those around every code's lower boundary (the distance at
// which the unrounded code is c - 1/2, and the 4 doubles either side of it), the planes, and infinity.
std::vector<double> probe_distances(const host::DepthCode& dc, size_t random, uint32_t boundary_stride) {
  std::vector<double> d;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(std::log(dc.near_m / 2), std::log(dc.far_m * 2));
  for (size_t i = 0; i < random; ++i) d.push_back(std::exp(u(rng)));
  const double L = std::log(dc.far_m / dc.near_m);
  for (uint64_t c = 1; c <= dc.max_code(); c += boundary_stride) {
    double x = dc.near_m * std::exp((static_cast<double>(c) - 0.5) / dc.max_code() * L);
    for (int i = 0; i < 4; ++i) x = std::nextafter(x, 0.0);
    for (int i = 0; i < 9; ++i, x = std::nextafter(x, 1e300)) d.push_back(x);
  }
  for (double x : {dc.near_m, std::nextafter(dc.near_m, 0.0), dc.far_m, std::nextafter(dc.far_m, 1e300), 0.0, 1e300})
    d.push_back(x);
  return d;
}

}  // namespace

TEST(FaceWords, DepthCodesInBulkAreCodeTexelByTexel) {
  struct Case {
    double near_m, far_m;
    int bits;
  };
  // The default; narrow and wide codes (20 bits: still the series; 24 and 32: code() throughout); a short
  // range (the series would be too coarse: code() throughout).
  for (const Case& k : {Case{0.05, 1000.0, 16}, Case{0.05, 1000.0, 8}, Case{0.05, 1000.0, 20}, Case{0.01, 50000.0, 24}, Case{0.05, 1000.0, 32},
                        Case{1.0, 1.0001, 16}}) {
    host::DepthCode dc;
    dc.near_m = k.near_m;
    dc.far_m = k.far_m;
    dc.bits = k.bits;
    const uint32_t stride = k.bits <= 16 ? 1 : 9973;  // every boundary of a 16-bit code; a sample of wider ones
    const std::vector<double> d = probe_distances(dc, 200000, stride);
    std::vector<uint32_t> got(d.size());
    dc.codes(d.data(), got.data(), d.size());
    int64_t wrong = 0;
    for (size_t i = 0; i < d.size(); ++i) {
      const uint32_t want = std::isinf(d[i]) ? dc.max_code() : dc.code(d[i]);
      if (got[i] != want && ++wrong <= 5)
        ADD_FAILURE() << "bits " << k.bits << " distance " << std::hexfloat << d[i] << std::defaultfloat << ": " << got[i] << ", code() "
                      << want;
    }
    EXPECT_EQ(wrong, 0) << "bits " << k.bits << " of " << d.size();
  }
  host::DepthCode dc;
  const double inf = std::numeric_limits<double>::infinity();
  uint32_t c = 0;
  dc.codes(&inf, &c, 1);
  EXPECT_EQ(c, dc.max_code());
}

TEST(FaceWords, ColoursRoundHalvesUpAndPackInTheMemorysFormat) {
  dp::MemoryConfig mc;
  mc.red_bits = 5;
  mc.green_bits = 6;
  mc.blue_bits = 5;
  const dp::MemoryFormat fmt(mc);
  const dp::Rgb8Packer pack(fmt);
  host::DepthCode dc;
  dc.bits = fmt.depth_bits;
  std::vector<glm::dvec3> color;
  std::vector<double> distance;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int v = 0; v <= 255; ++v) {  // every exact half, and the doubles beside it
    const double h = (v + 0.5) / 255.0;
    color.push_back({h, std::nextafter(h, 0.0), std::nextafter(h, 1.0)});
  }
  for (int i = 0; i < 5000; ++i) color.push_back({u(rng), u(rng), u(rng)});
  color.push_back({std::nan(""), -0.0, 1.0});
  for (size_t i = 0; i < color.size(); ++i) distance.push_back(i % 7 == 3 ? std::numeric_limits<double>::infinity() : 0.05 + 0.37 * static_cast<double>(i));
  std::vector<uint64_t> got(color.size());
  host::face_words(distance.data(), color.data(), color.size(), dc, pack, fmt.empty_word(), got.data());
  auto channel = [](double c) {  // independent: the library's rounding, halves away from zero
    const double v = std::isnan(c) ? 0.0 : std::min(std::max(c, 0.0), 1.0) * 255.0;
    return static_cast<int>(std::lround(v));
  };
  for (size_t i = 0; i < color.size(); ++i) {
    const uint64_t want = std::isinf(distance[i]) ? fmt.empty_word()
                                                  : (uint64_t{dc.code(distance[i])} << 32) |
                                                        fmt.pack_rgb8(channel(color[i].r), channel(color[i].g), channel(color[i].b));
    ASSERT_EQ(got[i], want) << "texel " << i << " colour " << color[i].r << " " << color[i].g << " " << color[i].b;
  }
}
