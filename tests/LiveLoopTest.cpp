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
    EXPECT_GE(f.index, k);  // (later when it fell behind: frames are dropped to keep up)
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

#include <chrono>
#include <glm/gtc/quaternion.hpp>
#include <thread>

#include "TestSupport.hpp"
#include "tracker/TraceFile.hpp"

namespace {

// A live source of the test's: a head turning about y at 90 deg/s, sampled at 10 kHz on the wall clock
// since its creation (ten times a DK1's rate, so the loop's window is reached in a short test).
class WallClockTurn : public tracker::PoseSource {
 public:
  static constexpr int64_t kStepPs = 100'000'000;  // 0.1 ms
  std::string describe() const override { return "test turn"; }
  bool live() const override { return true; }
  int64_t now_ps() const override {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0_).count() * 1000;
  }
  void poll(std::vector<tracker::PoseSample>& out, int timeout_ms) override {
    if (now_ps() < next_ * kStepPs) std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
    for (const int64_t now = now_ps(); next_ * kStepPs <= now; ++next_)
      if (plugged_) out.push_back(sample(next_));
  }
  bool connected() const override { return plugged_; }
  // Unplugged: no samples (those it would have made are lost), and not connected.
  void set_plugged(bool plugged) { plugged_ = plugged; }
  std::vector<std::string> take_events() override { return {}; }
  static tracker::PoseSample sample(int64_t j) {
    tracker::PoseSample p;
    p.time_ps = j * kStepPs;
    p.orientation = glm::angleAxis(glm::radians(90.0) * static_cast<double>(p.time_ps) * 1e-12, glm::dvec3(0, 1, 0));
    return p;
  }
  int64_t sent() const { return next_; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point t0_ = Clock::now();
  int64_t next_ = 0;
  bool plugged_ = true;
};

}  // namespace

// A live source is taken as it arrives, in order from the last sample received before the start, recorded
// as taken (--record-live), and held only a second behind the frame: a tracker's samples held whole would
// grow without bound (144 MB an hour at 1 kHz), as the loop held them until 2026-11-28.
TEST(LiveLoop, ALiveSourceIsTakenInOrderRecordedAndHeldInAWindow) {
  arp::test::TempDir d;
  sim::LiveSpec s;
  // (A 64 x 48 display at 60 Hz: 224 x 93 clocks a frame.)
  s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48", "display.pixel_clock_hz=1249920"});
  s.memories.scene = "";
  s.seconds = 3.0;
  s.record_live = d.file("took.csv");
  auto owned = std::make_unique<WallClockTurn>();
  const WallClockTurn& turn = *owned;
  sim::LiveLoop loop(s, std::move(owned));
  EXPECT_EQ(loop.source_name(), "test turn");
  size_t most_held = 0;
  while (!loop.finished()) {
    const sim::LiveFrame f = loop.next();
    EXPECT_LT(f.latency_max_ps, 100'000'000'000) << f.index;  // each pixel a fresh sample, never a stale held pose
    most_held = std::max(most_held, loop.samples_held());
  }
  loop.commit_record();
  const int64_t taken = loop.live_samples(), before = loop.live_samples_before_start();
  // Three seconds of a 10 kHz source (it makes its samples as it is polled): every one taken, or received
  // before the start. Held: a second behind the frame, up to when it is shown -- about 10 000, a third of
  // what was taken; less than 0.6 of it allows a starved machine 0.8 s between choosing a frame and taking its
  // samples (held whole, all of it: 30 000).
  EXPECT_EQ(taken + before, turn.sent());
  EXPECT_GT(taken, 25'000);
  EXPECT_LT(static_cast<double>(most_held), 0.6 * static_cast<double>(taken));
  // What was taken, as recorded: the source's samples in order from the last received before the start,
  // which is at the start; the rest on the source's 0.1 ms steps.
  const auto took = tracker::read_trace_csv(d.file("took.csv"));
  ASSERT_EQ(static_cast<int64_t>(took.size()), taken);
  for (size_t i = 0; i < took.size(); ++i) {
    const tracker::PoseSample want = WallClockTurn::sample(before + static_cast<int64_t>(i));
    ASSERT_EQ(took[i].time_ps, static_cast<int64_t>(i) * WallClockTurn::kStepPs) << i;
    // (17 digits give each double back; the trace reader normalises: an ulp apart)
    for (int c = 0; c < 4; ++c) ASSERT_NEAR(took[i].orientation[c], want.orientation[c], 1e-15) << i;
  }
}

// --record-live records live input: alone it is refused, naming it, before anything is opened.
TEST(LiveLoop, RecordLiveWithoutLiveInputIsRefused) {
  sim::LiveSpec s;
  s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48"});
  s.memories.scene = "";
  s.record_live = "took.csv";
  try {
    sim::LiveLoop loop(s);
    ADD_FAILURE() << "accepted --record-live without --live";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--record-live: took.csv: records the motion of live input"), std::string::npos) << e.what();
  }
}

// The loop keeps the display's pace from its first frame: its clock starts there (not when it was built:
// a window opened in between put every frame 0.3 s late), and a loop that fell behind shows the latest
// frame due, dropping those in between (it used to show each in turn, late, and stayed behind for good).
// The last frame is shown whatever happens.
TEST(LiveLoop, ALoopBehindTheDisplayDropsFramesToCatchUp) {
  sim::LiveSpec s;
  s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48", "display.pixel_clock_hz=1249920"});
  s.memories.scene = "";
  s.seconds = 2.0;
  sim::LiveLoop loop(s);
  ASSERT_EQ(loop.frames(), 120);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a window being opened
  const sim::LiveFrame first = loop.next();
  EXPECT_LT(first.index, 5);  // 0, or a few on a starved machine; 17 with the clock started at the construction
  EXPECT_EQ(first.dropped, first.index);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // a window slow to present: 12 periods
  const sim::LiveFrame caught_up = loop.next();
  EXPECT_GE(caught_up.index, first.index + 12);  // (frame k is due k + 1 periods after the first frame's start)
  EXPECT_EQ(caught_up.dropped, caught_up.index - first.index - 1);
  ASSERT_FALSE(loop.finished());
  std::this_thread::sleep_for(std::chrono::milliseconds(2000));  // past the end
  const sim::LiveFrame last = loop.next();
  EXPECT_EQ(last.index, 119);
  EXPECT_TRUE(loop.finished());
  EXPECT_EQ(loop.shown_frames(), 3);
  EXPECT_EQ(loop.dropped_frames(), 117);
}

// Unplugged for a while: the frames meanwhile say so and hold the last pose (their latency grows from the
// unplug), and after the replug the frames latch fresh samples again.
TEST(LiveLoop, FramesWhileTheTrackerIsUnpluggedSaySoAndHoldTheLastPose) {
  sim::LiveSpec s;
  s.config = config::apply_overrides({}, {"display.h_active=64", "display.v_active=48", "display.pixel_clock_hz=1249920"});
  s.memories.scene = "";
  s.seconds = 1.5;
  auto owned = std::make_unique<WallClockTurn>();
  WallClockTurn& turn = *owned;  // (the loop owns it and keeps it while it lives)
  sim::LiveLoop loop(s, std::move(owned));
  // Unplugged once frame 20 is shown, replugged once a frame 20 frames later has shown the unplug: a third
  // of a second with no samples, whatever frames are dropped.
  int64_t unplugged_at = -1, unplugged_frames = 0, held = 0, fresh_after = 0;
  bool replugged = false;
  while (!loop.finished()) {
    const sim::LiveFrame f = loop.next();
    if (f.disconnected) {
      EXPECT_FALSE(replugged) << f.index;
      ++unplugged_frames;
      // Each pixel latched the last pose before the unplug (taken as frame unplugged_at + 1 was shown, or a
      // frame later): older than the frames since.
      const double since_ps = static_cast<double>(f.index - unplugged_at - 2) * 1e12 / loop.refresh_hz();
      held += static_cast<double>(f.latency_min_ps) >= since_ps;
      if (f.index >= unplugged_at + 20) {
        turn.set_plugged(true);
        replugged = true;
      }
    } else if (replugged) {
      fresh_after += f.latency_max_ps < 100'000'000'000;  // < 100 ms: fresh samples again
    } else if (unplugged_at < 0 && f.index >= 20) {
      turn.set_plugged(false);
      unplugged_at = f.index;
    }
  }
  EXPECT_GT(unplugged_frames, 0);
  EXPECT_EQ(held, unplugged_frames);
  EXPECT_TRUE(replugged);
  EXPECT_GT(fresh_after, 0);
}
