#include <gtest/gtest.h>

#include <cmath>

#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"

using namespace arp::dp;

namespace {
uint64_t word(uint32_t color, uint32_t depth) { return (uint64_t{depth} << 32) | color; }
}  // namespace

TEST(CompositionUnit, NearestWinsTiesGoToTheLowerMemoryEmptyShowsBackground) {
  const MemoryFormat f;
  const CompositionParams p(f, {10, 20, 30});
  const uint64_t E = f.empty_word();
  {
    const uint64_t w[4] = {word(1, 500), word(2, 300), word(3, 400), E};
    const Composite c = compose(w, 4, p);
    EXPECT_EQ(c.color, 2u);
    EXPECT_EQ(c.memory, 1);
  }
  {
    const uint64_t w[4] = {E, word(5, 300), word(6, 300), word(7, 300)};  // exact tie
    EXPECT_EQ(compose(w, 4, p).memory, 1);
  }
  {
    const uint64_t w[3] = {E, E, E};
    const Composite c = compose(w, 3, p);
    EXPECT_EQ(c.color, f.pack_rgb8(10, 20, 30));
    EXPECT_EQ(c.memory, -1);
  }
  {
    const uint64_t w[2] = {word(0xFFFFFF, 0), word(1, 0)};  // depth 0: nearest possible
    EXPECT_EQ(compose(w, 2, p).color, 0xFFFFFFu);
  }
  {
    const uint64_t w[2] = {E, word(9, f.empty_depth() - 1)};  // the farthest real depth still shows
    EXPECT_EQ(compose(w, 2, p).color, 9u);
  }
}

TEST(AntiAliasingFilter, TapsAndWeightsAroundTexelCentres) {
  // u = 10.5 texels exactly on a texel centre: taps 10 and 11, weight 0 on 11.
  BilinearTaps t = bilinear_taps(int64_t{21} << 7, int64_t{21} << 7, 8, 512);
  EXPECT_EQ(t.x0, 10);
  EXPECT_EQ(t.x1, 11);
  EXPECT_EQ(t.wx, 0u);
  // u = 11.0: halfway between centres 10.5 and 11.5.
  t = bilinear_taps(int64_t{11} << 8, 0, 8, 512);
  EXPECT_EQ(t.x0, 10);
  EXPECT_EQ(t.wx, 128u);
  // At the face edges the taps clamp (no filtering across cube edges).
  EXPECT_EQ(t.y0, 0);
  EXPECT_EQ(t.y1, 0);
  t = bilinear_taps((int64_t{512} << 8) - 1, 0, 8, 512);
  EXPECT_EQ(t.x0, 511);
  EXPECT_EQ(t.x1, 511);
}

TEST(AntiAliasingFilter, BlendIsTheRoundedExactBilinear) {
  const MemoryFormat f;
  const ChannelLayout L(f);
  const uint32_t c00 = 0x000000, c10 = 0xFF8040, c01 = 0x10FF00, c11 = 0x0000FF;
  for (uint32_t wx = 0; wx < 256; wx += 5)
    for (uint32_t wy = 0; wy < 256; wy += 7) {
      const uint32_t got = bilinear_blend(c00, c10, c01, c11, wx, wy, 8, L);
      for (int c = 0; c < 3; ++c) {
        auto ch = [&](uint32_t v) { return static_cast<double>((v >> (16 - 8 * c)) & 0xFF); };
        const double fx = wx / 256.0, fy = wy / 256.0;
        const double exact = (1 - fy) * ((1 - fx) * ch(c00) + fx * ch(c10)) + fy * ((1 - fx) * ch(c01) + fx * ch(c11));
        ASSERT_EQ(ch(got), std::floor(exact + 0.5)) << "wx=" << wx << " wy=" << wy << " c=" << c;
      }
    }
  EXPECT_EQ(bilinear_blend(c00, c10, c01, c11, 0, 0, 8, L), c00);
}

TEST(HmdScanOut, RescalesMemoryColourToTheDisplayAndGivesPhotonTimes) {
  MemoryFormat f;
  f.red_bits = 5;
  f.green_bits = 6;
  f.blue_bits = 5;
  PipelineConfig p;
  const HmdScanOut s(f, p);
  EXPECT_EQ(s.to_display(0xFFFF), 0xFFFFFFu);
  EXPECT_EQ(s.to_display(0), 0u);
  EXPECT_EQ(s.to_display(f.pack_color(16, 32, 0)), (132u << 16) | (130u << 8));  // 16*255/31 = 131.6, 32*255/63 = 129.5
  const HmdScanOut same(MemoryFormat{}, p);
  EXPECT_EQ(same.to_display(0x123456), 0x123456u);
  p.photon_delay_ps = 5000;
  const VideoTiming t{VideoTimingConfig{}};
  EXPECT_EQ(HmdScanOut::photon_time_ps(t, p, 0, 0, 0, 0), 5000);
  EXPECT_EQ(HmdScanOut::photon_time_ps(t, p, 1, 1, 1, 0), t.cycles_to_ps(420001) + 5000);
}
