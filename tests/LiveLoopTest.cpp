// The live loop as a library (no window): synthetic motion "until stopped" is
// generated as the frames need it, so the loop starts at once and its memory
// stays flat (it used to precompute an hour: 1.16 GB resident, 2.6 s).
#include <gtest/gtest.h>

#include "common/ResourceUsage.hpp"
#include "sim/ConfigFile.hpp"
#include "sim/LiveLoop.hpp"

using namespace arp;

TEST(LiveLoop, SyntheticMotionUntilStoppedIsGeneratedAsNeeded) {
  sim::LiveSpec s;
  s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48"});
  s.memories.scene = "";
  const int64_t before = current_resident_bytes();
  ASSERT_GT(before, 0);
  sim::LiveLoop loop(s);  // seconds 0: until stopped
  EXPECT_EQ(loop.frames(), INT64_MAX);
  EXPECT_EQ(loop.source_name(), "synthetic shake");
  int64_t worst = 0;
  for (int k = 0; k < 6; ++k) {
    const sim::LiveFrame f = loop.next();
    EXPECT_EQ(f.index, k);
    // Every pixel latched a sample of the motion shortly before its photon (the motion covers the frame).
    EXPECT_GE(f.latency_min_ps, 0);
    EXPECT_LT(f.latency_max_ps, 100'000'000'000) << k;  // < 100 ms: a 1 kHz motion, never a stale held pose
    worst = std::max(worst, current_resident_bytes() - before);
  }
  // A day of 1 kHz motion held whole would be gigabytes; the window is two seconds of it.
  EXPECT_LT(worst, 64 << 20);
}
