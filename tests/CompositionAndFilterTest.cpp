#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/stages/CompositionStage.hpp"
#include "rtl_model/stages/FilterStage.hpp"

using namespace arp::dp;

namespace {
uint64_t word(uint32_t color, uint32_t depth) { return (uint64_t{depth} << 32) | color; }
// A bilinear pipeline of n memories, background (10, 20, 30), and its composition stage.
arp::stage::TimedInputs bilinear_inputs(int memories) {
  arp::stage::TimedInputs in;
  in.config.memory.count = memories;
  in.config.memory.background = {10, 20, 30};
  in.config.pipeline.aa = AaMode::Bilinear;
  return in;
}
struct CompositionBench {
  explicit CompositionBench(int n) : in(bilinear_inputs(n)), ctx{in, PipelineSchedule(in.config)}, stage(ctx) {}
  arp::stage::TimedInputs in;
  arp::stage::StageContext ctx;
  arp::stage::CompositionStage stage;
  uint32_t empty = MemoryFormat(in.config.memory).empty_depth();
  uint32_t background = MemoryFormat(in.config.memory).pack_rgb8(10, 20, 30);
};
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

// compose_held over a mask is compose over every input with the ones not held made empty: the colour,
// the depth and the winning memory, every mask of eight inputs, ties and empty inputs common.
TEST(CompositionUnit, ComposingTheHeldInputsIsComposingAllWithTheRestEmpty) {
  const MemoryFormat f;
  const CompositionParams p(f, {10, 20, 30});
  std::mt19937 rng(7);
  for (uint32_t held = 0; held < 256; ++held)
    for (int i = 0; i < 20; ++i) {
      uint64_t words[kCompositionInputs], with_empty[kCompositionInputs];
      for (int m = 0; m < kCompositionInputs; ++m) {
        const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
        const uint32_t depth = kind == 0 ? f.empty_depth() : std::uniform_int_distribution<uint32_t>(0, 2)(rng);
        words[m] = word(std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng), depth);
        with_empty[m] = held >> m & 1u ? words[m] : f.empty_word();
        if (!(held >> m & 1u)) words[m] = word(0xabcdef, 0);  // not held: would win if it were read
      }
      const Composite a = compose_held(words, held, p), b = compose(with_empty, kCompositionInputs, p);
      ASSERT_EQ(a.color, b.color) << "held " << held;
      ASSERT_EQ(a.depth, b.depth) << "held " << held;
      ASSERT_EQ(a.memory, b.memory) << "held " << held;
    }
}

// The timed models' composition stage takes the memory count as a constant (one case per count): each
// count composes as the rule says -- the smallest depth code, the lower memory on a tie, the background
// where all are empty -- for both eyes and every tap, with the words past the count ignored.
TEST(CompositionUnit, TheStageComposesEveryMemoryCountByTheRule) {
  for (int n = 1; n <= kCompositionInputs; ++n) {
    const CompositionBench b(n);
    const arp::stage::CompositionStage& stage = b.stage;
    const uint32_t empty = b.empty, background = b.background;
    std::mt19937 rng(static_cast<uint32_t>(n));
    for (int i = 0; i < 400; ++i) {
      arp::stage::FetchToken t{};
      t.slot.eye_count = 2;
      t.memories = static_cast<uint8_t>(n);
      t.taps = 4;
      for (int e = 0; e < 2; ++e)
        for (int tap = 0; tap < 4; ++tap)
          for (int m = 0; m < kCompositionInputs; ++m) {
            // Few depths, so ties are common; a quarter empty; past the count, the nearest possible word.
            const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
            const uint32_t depth = m >= n ? 0 : (kind == 0 ? empty : std::uniform_int_distribution<uint32_t>(0, 3)(rng));
            t.words[e][tap][m] = word(std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng), depth);
          }
      arp::stage::ComposedToken out{};
      stage.compute(t, out);
      for (int e = 0; e < 2; ++e)
        for (int tap = 0; tap < 4; ++tap) {
          const uint64_t* w = t.words[e][tap];
          int best = 0;
          for (int m = 1; m < n; ++m)
            if ((w[m] >> 32) < (w[best] >> 32)) best = m;
          const uint32_t want = (w[best] >> 32) == empty ? background : static_cast<uint32_t>(w[best]);
          ASSERT_EQ(out.tap_color[e][tap], want) << n << " memories, token " << i << " eye " << e << " tap " << tap;
        }
    }
  }
}

// The memory read leaves out the memories whose face was never written (FetchToken::held): the stage
// composes the others as if those were empty -- whatever their words hold, here the nearest possible
// depth, which would win if it were read. Every mask of held memories, every count.
TEST(CompositionUnit, TheStageComposesOnlyTheMemoriesHeld) {
  for (int n = 1; n <= kCompositionInputs; ++n) {
    const CompositionBench b(n);
    const arp::stage::CompositionStage& stage = b.stage;
    const uint32_t empty = b.empty, background = b.background;
    std::mt19937 rng(static_cast<uint32_t>(100 + n));
    for (uint32_t mask = 0; mask < (1u << n); ++mask)
      for (int i = 0; i < 12; ++i) {
        arp::stage::FetchToken t{};
        t.slot.eye_count = 2;
        t.memories = static_cast<uint8_t>(n);
        t.taps = 4;
        t.held[0] = static_cast<uint8_t>(mask);
        t.held[1] = static_cast<uint8_t>(std::uniform_int_distribution<uint32_t>(0, (1u << n) - 1)(rng));
        for (int e = 0; e < 2; ++e)
          for (int tap = 0; tap < 4; ++tap)
            for (int m = 0; m < kCompositionInputs; ++m) {
              const bool held = m < n && (t.held[e] >> m & 1u);
              const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
              const uint32_t depth = !held ? 0 : (kind == 0 ? empty : std::uniform_int_distribution<uint32_t>(0, 3)(rng));
              t.words[e][tap][m] = word(std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng), depth);
            }
        arp::stage::ComposedToken out{};
        stage.compute(t, out);
        for (int e = 0; e < 2; ++e)
          for (int tap = 0; tap < 4; ++tap) {
            uint32_t best_depth = empty, want = background;
            for (int m = 0; m < n; ++m) {
              const uint64_t w = t.words[e][tap][m];
              if ((t.held[e] >> m & 1u) && (w >> 32) < best_depth) {
                best_depth = static_cast<uint32_t>(w >> 32);
                want = static_cast<uint32_t>(w);
              }
            }
            ASSERT_EQ(out.tap_color[e][tap], want)
                << n << " memories, held " << int{t.held[e]} << ", token " << i << " eye " << e << " tap " << tap;
          }
      }
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

// The 32-bit accumulator gives the 64-bit one's value wherever blend_fits_32 allows it, and the check is
// exact: its bound is the sum with every channel at its largest and zero weights, m W^2 + W^2 / 2, which
// for 8-bit channels fits 32 bits up to texel_frac 12 and for 16-bit ones up to 8 -- one bit more and the
// narrow sum wraps.
TEST(AntiAliasingFilter, TheNarrowAccumulatorBlendsAlikeWhereItFits) {
  for (const int red : {8, 16}) {
    MemoryConfig mc;
    mc.red_bits = red;
    mc.green_bits = mc.blue_bits = 8;
    const ChannelLayout L{MemoryFormat(mc)};
    const int last_fit = red == 16 ? 8 : 12;
    for (int T = 1; T <= 16; ++T) {
      EXPECT_EQ(blend_fits_32(T, L), T <= last_fit) << "red " << red << " T " << T;
      const uint32_t top = (L.mask[0] << L.shift[0]) | (L.mask[1] << L.shift[1]) | L.mask[2];
      const uint32_t W = 1u << T;
      if (!blend_fits_32(T, L)) {
        if (T == last_fit + 1) {  // the largest sum no longer fits: the narrow one differs
          EXPECT_NE(bilinear_blend_in<uint32_t>(top, top, top, top, 0, 0, T, L), bilinear_blend(top, top, top, top, 0, 0, T, L));
        }
        continue;
      }
      uint32_t state = 12345u + static_cast<uint32_t>(T);
      auto next = [&] { return state = state * 1664525u + 1013904223u; };
      for (int k = 0; k < 2000; ++k) {
        const bool extreme = k < 16;  // every corner of colours and weights first
        const uint32_t c00 = extreme && (k & 1) ? top : next() & top, c10 = extreme && (k & 2) ? top : next() & top;
        const uint32_t c01 = extreme && (k & 4) ? top : next() & top, c11 = extreme && (k & 8) ? top : next() & top;
        const uint32_t wx = extreme ? (k & 1 ? W - 1 : 0) : next() % W, wy = extreme ? (k & 2 ? W - 1 : 0) : next() % W;
        ASSERT_EQ(bilinear_blend_in<uint32_t>(c00, c10, c01, c11, wx, wy, T, L), bilinear_blend(c00, c10, c01, c11, wx, wy, T, L))
            << "red " << red << " T " << T << " k " << k;
      }
    }
  }
}

// The filter stage blends the default 8-8-8 format through a layout fixed at compile time and any
// other through the configured one: each channel the exact bilinear value rounded half up, worked out
// in double (exact for these widths), in every format tried.
TEST(AntiAliasingFilter, TheStageBlendsEveryFormatAsTheClosedForm) {
  for (const std::array<int, 3> bits : {std::array<int, 3>{8, 8, 8}, {5, 6, 5}, {16, 8, 8}, {8, 8, 7}, {4, 4, 4}}) {
    arp::stage::TimedInputs in;
    in.config.memory.red_bits = bits[0];
    in.config.memory.green_bits = bits[1];
    in.config.memory.blue_bits = bits[2];
    in.config.pipeline.aa = AaMode::Bilinear;
    const int T = in.config.widths.texel_frac;
    const arp::stage::StageContext ctx{in, PipelineSchedule(in.config)};
    const arp::stage::FilterStage stage(ctx);
    const ChannelLayout L{MemoryFormat(in.config.memory)};
    EXPECT_EQ((FixedChannelLayout<8, 8, 8>::same(L)), bits == (std::array<int, 3>{8, 8, 8}));
    const uint32_t all = (L.mask[0] << L.shift[0]) | (L.mask[1] << L.shift[1]) | L.mask[2];
    std::mt19937 rng(static_cast<uint32_t>(bits[0] * 100 + bits[1] * 10 + bits[2]));
    for (int i = 0; i < 3000; ++i) {
      arp::stage::ComposedToken t{};
      t.slot.eye_count = 2;
      for (int e = 0; e < 2; ++e) {
        const bool corner = i < 16;  // all-ones colours and the weights' ends first
        for (int tap = 0; tap < 4; ++tap) t.tap_color[e][tap] = corner && (i >> tap & 1) ? all : rng() & all;
        t.wx[e] = corner ? (i & 1 ? (1u << T) - 1 : 0) : rng() % (1u << T);
        t.wy[e] = corner ? (i & 2 ? (1u << T) - 1 : 0) : rng() % (1u << T);
      }
      arp::stage::ColorToken out{};
      stage.compute(t, out);
      for (int e = 0; e < 2; ++e)
        for (int c = 0; c < 3; ++c) {
          auto ch = [&](uint32_t v) { return static_cast<double>((v >> L.shift[c]) & L.mask[c]); };
          const uint32_t* q = t.tap_color[e];
          const double fx = t.wx[e] / double(1u << T), fy = t.wy[e] / double(1u << T);
          const double exact = (1 - fy) * ((1 - fx) * ch(q[0]) + fx * ch(q[1])) + fy * ((1 - fx) * ch(q[2]) + fx * ch(q[3]));
          ASSERT_EQ(ch(out.color[e]), std::floor(exact + 0.5))
              << bits[0] << "-" << bits[1] << "-" << bits[2] << " token " << i << " eye " << e << " channel " << c;
        }
    }
  }
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
