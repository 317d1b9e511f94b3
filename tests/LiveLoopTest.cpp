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
  size_t most_held = 0;
  for (int k = 0; k < 6; ++k) {
    const sim::LiveFrame f = loop.next();
    EXPECT_EQ(f.index, k);
    // Every pixel latched a sample of the motion shortly before its photon (the motion covers the frame).
    EXPECT_GE(f.latency_min_ps, 0);
    EXPECT_LT(f.latency_max_ps, 100'000'000'000) << k;  // < 100 ms: a 1 kHz motion, never a stale held pose
    worst = std::max(worst, current_resident_bytes() - before);
    most_held = std::max(most_held, loop.samples_held());
  }
  // The window: from a second before frame k to a second past frame k + 2, at 1 kHz: at least the second
  // ahead, at most two seconds and three frames (a day of motion held whole would be 86 million samples).
  const double frame_samples = 1000.0 / loop.refresh_hz();
  EXPECT_GE(most_held, 1000u);
  EXPECT_LE(static_cast<double>(most_held), 2000.0 + 3 * frame_samples + 2);
#if !defined(__SANITIZE_ADDRESS__)
  // And the process: a day of 1 kHz motion held whole would be gigabytes. (Not under ASan, whose
  // quarantine keeps freed memory resident: 174 MB there.)
  EXPECT_LT(worst, 64 << 20);
#endif
}

#include "common/InputError.hpp"

// --device chooses the tracker of --live usb: given without it (with a trace, or alone) it is refused,
// not ignored.
TEST(LiveLoop, ADeviceWithoutLiveInputIsRefused) {
  for (const std::string trace : {"", "some.csv"}) {
    sim::LiveSpec s;
    s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48"});
    s.memories.scene = "";
    s.trace = trace;
    s.tracker.device = "1:2";
    try {
      sim::LiveLoop loop(s);
      ADD_FAILURE() << "accepted --device with trace '" << trace << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--device: 1:2: chooses the tracker of --live usb"), std::string::npos) << e.what();
    }
  }
  // --mag-calibrate the same way, and it needs --mag-yaw.
  tracker::TrackerChoice calibrate_only;
  calibrate_only.mag_calibrate = true;
  try {
    tracker::live_source("", calibrate_only);
    ADD_FAILURE() << "accepted --mag-calibrate without --live";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--mag-calibrate"), std::string::npos) << e.what();
  }
  try {
    calibrate_only.stream_options();
    ADD_FAILURE() << "accepted --mag-calibrate without --mag-yaw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give --mag-yaw GAIN too"), std::string::npos) << e.what();
  }
}
