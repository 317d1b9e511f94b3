#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>

#include "rtl_model/datapath/VideoTiming.hpp"

using namespace arp::dp;

TEST(VideoTiming, DefaultIsVga640x480At60Hz) {
  const VideoTiming t{VideoTimingConfig{}};
  EXPECT_EQ(t.config().h_total(), 800);
  EXPECT_EQ(t.config().v_total(), 525);
  EXPECT_EQ(t.frame_cycles(), 420000);
  EXPECT_NEAR(t.refresh_hz(), 59.94, 0.001);
  // One pixel period of 25.175 MHz is 39721.946 ps; times are floored picoseconds.
  EXPECT_EQ(t.cycles_to_ps(1), 39721);
  EXPECT_EQ(t.cycles_to_ps(420000), 16683217477);  // 16.683 ms frame
}

TEST(VideoTiming, PixelCyclesFollowTheRasterAndEyesAreLockstep) {
  const VideoTiming t{VideoTimingConfig{}};
  EXPECT_EQ(t.pixel_cycle(0, 0, 0, 0), 0);
  EXPECT_EQ(t.pixel_cycle(0, 0, 639, 0), 639);
  EXPECT_EQ(t.pixel_cycle(0, 0, 0, 1), 800);  // blanking after each active line
  EXPECT_EQ(t.pixel_cycle(0, 1, 17, 9), t.pixel_cycle(0, 0, 17, 9));
  EXPECT_EQ(t.pixel_cycle(3, 0, 0, 0), 3 * 420000);
  EXPECT_EQ(t.line_start_cycle(2, 479), 2 * 420000 + 479 * 800);
}

TEST(VideoTiming, SideBySidePanelScansLeftEyeThenRight) {
  VideoTimingConfig c;
  c.eye_scan = EyeScan::SideBySide;
  const VideoTiming t{c};
  EXPECT_EQ(c.h_total(), 2 * 640 + 160);
  EXPECT_EQ(t.pixel_cycle(0, 1, 0, 0), 640);
  EXPECT_EQ(t.pixel_cycle(0, 1, 5, 2), 2 * c.h_total() + 645);
}

TEST(VideoTiming, InterlacedFieldsHoldAlternateLines) {
  VideoTimingConfig c;
  c.fields_per_frame = 2;
  const VideoTiming t{c};
  EXPECT_EQ(t.field_cycles(), 210000);
  EXPECT_EQ(t.field_of_line(0), 0);
  EXPECT_EQ(t.field_of_line(1), 1);
  EXPECT_EQ(t.line_start_cycle(0, 2), 800);         // second line of field 0
  EXPECT_EQ(t.line_start_cycle(0, 1), 210000);      // first line of field 1
  EXPECT_EQ(t.line_start_cycle(0, 3), 210000 + 800);
  EXPECT_LT(t.pixel_cycle(0, 0, 639, 478), t.pixel_cycle(0, 0, 0, 1));  // field 0 ends before field 1 starts
}

TEST(VideoTiming, PicosecondConversionsAreExactInversesOverAnHour) {
  const VideoTiming t{VideoTimingConfig{}};
  std::mt19937_64 rng(7);
  const int64_t hour_cycles = int64_t{25'175'000} * 3600;
  std::uniform_int_distribution<int64_t> d(0, hour_cycles);
  for (int i = 0; i < 20000; ++i) {
    const int64_t c = d(rng);
    const int64_t ps = t.cycles_to_ps(c);
    ASSERT_EQ(t.ps_to_cycle_floor(ps), c) << c;
    ASSERT_EQ(t.ps_to_cycle_floor(ps - 1), c - 1) << c;  // strictly before this cycle's start
    ASSERT_LT(t.cycles_to_ps(c), t.cycles_to_ps(c + 1));
  }
  EXPECT_EQ(t.cycles_to_ps(hour_cycles), int64_t{3600} * 1'000'000'000'000);
}

TEST(VideoTiming, ConversionsAtFarExtremes) {
  VideoTimingConfig c;
  c.pixel_clock_hz = 100'000'000'000;  // 100 GHz: the fastest clock allowed
  const VideoTiming fast{c};
  EXPECT_EQ(fast.cycles_to_ps(1), 10);
  c.pixel_clock_hz = 1000;  // the slowest
  const VideoTiming slow{c};
  EXPECT_EQ(slow.cycles_to_ps(1), 1'000'000'000);
  // 30 days of 25 MHz cycles: cycles * 1e12 overflows 64 bits, the 128-bit
  // intermediate does not (the int64 picosecond timeline itself spans +-106 days).
  const VideoTiming t{VideoTimingConfig{}};
  const int64_t month = int64_t{25'175'000} * 3600 * 24 * 30;
  EXPECT_EQ(t.cycles_to_ps(month), int64_t{3600} * 24 * 30 * 1'000'000'000'000);
  EXPECT_EQ(t.ps_to_cycle_floor(t.cycles_to_ps(month)), month);
  EXPECT_EQ(t.cycles_to_ps(-1), -39722);  // floor, also before time zero
}

// Time is int64 picoseconds: 2^63 - 1 ps is 106.75 days (a closed form, not
// the code's). The last frame in range has every time of itself and of the
// frame after it representable; a frame further is refused by name, and a
// cycle past the range is an overflow error, never a wrapped time.
TEST(VideoTiming, TimesPastThe64BitPicosecondRangeAreRefusedNotWrapped) {
  for (const int64_t hz : {int64_t{25'175'000}, int64_t{1000}, int64_t{100'000'000'000}}) {
    VideoTimingConfig c;
    c.pixel_clock_hz = hz;
    const VideoTiming t{c};
    const double range_s = 9223372036854775807.0 * 1e-12;  // 106.75 days
    const double frame_s = static_cast<double>(t.frame_cycles()) / static_cast<double>(hz);
    const int64_t last = t.last_frame_in_range();
    EXPECT_NEAR(static_cast<double>(last), std::floor(range_s / frame_s) - 2, 1.0) << hz;
    EXPECT_NO_THROW(t.cycles_to_ps(t.frame_start_cycle(last + 2))) << hz;
    EXPECT_THROW(t.cycles_to_ps(t.frame_start_cycle(last + 4)), std::overflow_error) << hz;
    EXPECT_GT(t.cycles_to_ps(t.frame_start_cycle(last + 2)), t.cycles_to_ps(t.frame_start_cycle(last + 1)));  // no wrap
    EXPECT_EQ(t.frames_out_of_range(0, last + 1), "") << hz;
    EXPECT_EQ(t.frames_out_of_range(last, 1), "") << hz;
    const std::string why = t.frames_out_of_range(last, 2);
    EXPECT_NE(why.find("frame " + std::to_string(last + 1) + " is past"), std::string::npos) << why;
    EXPECT_NE(why.find("frame " + std::to_string(last) + " ("), std::string::npos) << why;  // the limit stated
    EXPECT_NE(t.frames_out_of_range(INT64_MAX, INT64_MAX).find("or more"), std::string::npos);
    EXPECT_NE(t.frames_out_of_range(-1, 1), "");
  }
  // Far before time zero too: floored, and refused past the range.
  const VideoTiming t{VideoTimingConfig{}};
  EXPECT_EQ(t.cycles_to_ps(-1), -39722);
  EXPECT_THROW(t.cycles_to_ps(INT64_MIN / 2), std::overflow_error);
  // The inverse at the range's ends stays exact.
  const int64_t c_last = t.frame_start_cycle(t.last_frame_in_range() + 2);
  EXPECT_EQ(t.ps_to_cycle_floor(t.cycles_to_ps(c_last)), c_last);
  EXPECT_EQ(t.ps_to_cycle_floor(t.cycles_to_ps(c_last) - 1), c_last - 1);
}
