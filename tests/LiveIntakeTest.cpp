// What a live run takes from its source (sim::LiveIntake, for `run --live usb`
// and `arpsim live`), against a scripted source whose arrivals, clock and
// connection the test sets: the timeline fixed by arrival at the start, the
// replug after an unplug across the start timed from the source's clock, late
// samples counted and not taken, and the recording exactly what was taken.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>

#include "TestSupport.hpp"
#include "sim/LiveIntake.hpp"
#include "tracker/TraceFile.hpp"

using namespace arp;

namespace {

constexpr int64_t kMs = 1'000'000'000;  // picoseconds

// Hands over what the test queued, on a clock and a connection the test sets.
class ScriptedLiveSource : public tracker::PoseSource {
 public:
  std::vector<tracker::PoseSample> queued;
  int64_t now = 0;
  bool plugged = true;
  std::string describe() const override { return "scripted"; }
  bool live() const override { return true; }
  void poll(std::vector<tracker::PoseSample>& out, int) override {
    out.insert(out.end(), queued.begin(), queued.end());
    queued.clear();
  }
  int64_t now_ps() const override { return now; }
  std::vector<std::string> take_events() override { return {}; }
  bool connected() const override { return plugged; }
};

// A yaw of `deg` at device time `ms`: each sample told apart by its orientation.
tracker::PoseSample yaw_at(int64_t ms, double deg) {
  tracker::PoseSample p;
  p.time_ps = ms * kMs;
  p.orientation = glm::angleAxis(glm::radians(deg), glm::dvec3(0, 1, 0));
  return p;
}

double yaw_deg(const dp::Quat& q) { return glm::degrees(2.0 * std::atan2(q.y, q.w)); }

}  // namespace

// Received during the set-up: the last is where the head is at the start and is taken there; what arrives
// later is placed after it by the device's time, however far the device's clock is from the source's now
// (a transport slower than the device). The others are counted as received before the start.
TEST(LiveIntake, TheLastSampleReceivedIsThePoseAtTheStart) {
  ScriptedLiveSource src;
  src.queued = {yaw_at(100, 1), yaw_at(101, 2), yaw_at(102, 3)};
  src.now = 900 * kMs;  // the device's samples arrive 0.8 s behind its clock
  sim::LiveIntake in(src, "");
  auto stream = dp::OrientationStream::constant(dp::Quat{});
  const int64_t start = 5 * kMs;
  in.start(stream, start, "scripted");
  EXPECT_EQ(in.taken(), 1);
  EXPECT_EQ(in.before_start(), 2);
  ASSERT_EQ(stream.size(), 2u);
  EXPECT_EQ(stream[1].time_ps, start);
  EXPECT_NEAR(yaw_deg(stream[1].q), 3, 1e-9);
  std::vector<tracker::PoseSample> got = {yaw_at(103, 4), yaw_at(110, 5)};
  in.take(stream, got, "scripted");
  EXPECT_EQ(in.taken(), 3);
  ASSERT_EQ(stream.size(), 4u);
  EXPECT_EQ(stream[2].time_ps, start + 1 * kMs);
  EXPECT_EQ(stream[3].time_ps, start + 8 * kMs);
  EXPECT_NEAR(yaw_deg(stream[3].q), 5, 1e-9);
}

// Unplugged across the start: the last sample received is from before the unplug, and the device's clock
// after the replug has moved on by the time it was away. The timeline is then the source's clock at the
// start: what comes after the replug is placed by its time against that, not 0.5 s late against the old
// sample. The old sample is still the held pose at the start.
TEST(LiveIntake, ATrackerUnpluggedAcrossTheStartIsTimedFromItsClock) {
  ScriptedLiveSource src;
  src.queued = {yaw_at(1000, 7)};
  src.plugged = false;
  src.now = 1500 * kMs;  // unplugged at 1.0 s, the run starting at 1.5 s
  sim::LiveIntake in(src, "");
  auto stream = dp::OrientationStream::constant(dp::Quat{});
  in.start(stream, 0, "scripted");
  ASSERT_EQ(stream.size(), 2u);
  EXPECT_EQ(stream[1].time_ps, 0);
  EXPECT_NEAR(yaw_deg(stream[1].q), 7, 1e-9);
  src.plugged = true;  // replugged: the device's samples go on from its clock
  in.take(stream, {yaw_at(1600, 8)}, "scripted");
  ASSERT_EQ(stream.size(), 3u);
  EXPECT_EQ(stream[2].time_ps, 100 * kMs);
  // Nothing received at all: the source's clock as well. The pose the stream holds at the start (its reset
  // value) is taken there, so a recording begins at the start (a replay holds a trace's first sample back to
  // it: without this it would show the first sample too early).
  arp::test::TempDir d;
  ScriptedLiveSource quiet;
  quiet.now = 40 * kMs;
  sim::LiveIntake none(quiet, d.file("none.csv"));
  auto still = dp::OrientationStream::constant(dp::Quat{0.6, 0.0, 0.8, 0.0});
  none.start(still, 3 * kMs, "scripted");
  EXPECT_EQ(none.taken(), 1);
  EXPECT_EQ(none.before_start(), 0);
  ASSERT_EQ(still.size(), 2u);
  EXPECT_EQ(still[1].time_ps, 3 * kMs);
  none.take(still, {yaw_at(41, 1)}, "scripted");
  ASSERT_EQ(still.size(), 3u);
  EXPECT_EQ(still[2].time_ps, 4 * kMs);
  none.commit_record();
  const auto took = tracker::read_trace_csv(d.file("none.csv"));
  ASSERT_EQ(took.size(), 2u);
  EXPECT_EQ(took[0].time_ps, 3 * kMs);
  EXPECT_EQ(took[0].orientation, glm::dquat(0.6, 0.0, 0.8, 0.0));
  EXPECT_EQ(took[1].time_ps, 4 * kMs);
}

// A sample earlier than the stream holds is not taken: counted as received before the start when it is
// timed before the start (a report's older samples, handed over after it), else as out of order (its time
// stepped back). The recording is exactly what was taken, in order, on the run's timeline -- the trace
// `run --trace` replays.
TEST(LiveIntake, LateSamplesAreCountedNotTakenAndTheRecordingIsWhatWasTaken) {
  arp::test::TempDir d;
  ScriptedLiveSource src;
  src.queued = {yaw_at(10, 1)};
  sim::LiveIntake in(src, d.file("took.csv"));
  EXPECT_TRUE(in.recording());
  auto stream = dp::OrientationStream::constant(dp::Quat{});
  in.start(stream, 2 * kMs, "scripted");
  in.take(stream, {yaw_at(12, 2), yaw_at(11, 3), yaw_at(13, 4)}, "scripted");
  EXPECT_EQ(in.taken(), 3);
  EXPECT_EQ(in.before_start(), 0);
  EXPECT_EQ(in.out_of_order(), 1);  // 11 ms after 12 ms, both after the start (10 ms on the source's clock)
  in.take(stream, {yaw_at(9, 5), yaw_at(8, 6)}, "scripted");  // before the start, handed over late
  EXPECT_EQ(in.taken(), 3);
  EXPECT_EQ(in.before_start(), 2);
  EXPECT_EQ(in.out_of_order(), 1);
  EXPECT_EQ(in.recorded(), 3);
  EXPECT_FALSE(std::filesystem::exists(d.file("took.csv")));  // written only on commit
  in.commit_record();
  const auto took = tracker::read_trace_csv(d.file("took.csv"));
  ASSERT_EQ(took.size(), 3u);
  const int64_t want_ps[] = {2 * kMs, 4 * kMs, 5 * kMs};
  const double want_deg[] = {1, 2, 4};
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(took[i].time_ps, want_ps[i]) << i;
    EXPECT_NEAR(glm::degrees(glm::angle(took[i].orientation)), want_deg[i], 1e-9) << i;
  }
  // An intake whose recording is never committed leaves nothing behind.
  { sim::LiveIntake dropped(src, d.file("dropped.csv")); }
  EXPECT_FALSE(std::filesystem::exists(d.file("dropped.csv")));
}
