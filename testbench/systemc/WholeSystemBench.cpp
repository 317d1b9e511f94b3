// Whole-system benches: a run through each timed level equals the functional
// model bit for bit (frames, photon times, latency reports); host writes swap
// at the right vertical blank; a stalled stage fills the FIFOs and shows up as
// counted underflows at scan-out. Each TEST is one simulation (one process).
#include <gtest/gtest.h>

#include "BenchSupport.hpp"
#include "common/InputError.hpp"
#include "rtl_model/stages/HostWritePort.hpp"

using namespace arp;
using namespace arp::bench;

namespace {

struct Case {
  const char* name;
  scm::Fidelity level;
  dp::ArpConfig config;
};

// The same contents twice: the functional reference reads one, the timed run the other (host writes change it).
struct MemoryPair {
  MemoryPair(const dp::MemoryConfig& m, int eyes) : timed(m, eyes), ref(m, eyes) {
    fill_memories(timed);
    fill_memories(ref);
  }
  dp::DisplayMemorySet timed, ref;
};

dp::ArpConfig variant(const std::string& v) {
  dp::ArpConfig c = small_config();
  if (v == "default") return c;
  if (v == "per_pixel_latch") {
    c.pipeline.latch = dp::LatchPolicy::PerPixel;
    c.pipeline.latch_lead_cycles = 7;
  } else if (v == "per_frame_nearest_exact") {
    c.pipeline.latch = dp::LatchPolicy::PerFrame;
    c.pipeline.aa = dp::AaMode::Off;
    c.widths.divider = dp::DividerKind::Exact;
  } else if (v == "side_by_side") {
    c.timing.eye_scan = dp::EyeScan::SideBySide;
    c.pipeline.latch = dp::LatchPolicy::PerPixel;
  } else if (v == "interlaced_mono") {
    c.timing.eyes = 1;
    c.timing.fields_per_frame = 2;
    c.timing.v_back_porch = 7;  // odd total lines: fields end mid-line
    c.pipeline.latch = dp::LatchPolicy::PerField;
  } else if (v == "deep_narrow") {
    for (auto& s : c.timed.stage) s.latency_cycles = 5;
    c.timed.fifo_depth = 10;
    c.timed.issue_slack_cycles = 8;
    c.memory.count = 2;
    c.memory.red_bits = 5;
    c.memory.green_bits = 6;
    c.memory.blue_bits = 5;
    c.pipeline.display_bits = 6;
  }
  return c;
}

// "" when equal, else where the first difference is and how many there are.
template <class V>
std::string first_difference(const V& got, const HmdFrame& want, bool photon = false) {
  const V& w = [&]() -> const V& {
    if constexpr (std::is_same_v<V, std::vector<int64_t>>) return want.photon_ps;
    else return want.pixels;
  }();
  (void)photon;
  if (got.size() != w.size()) return "sizes differ";
  size_t n = 0, first = got.size();
  for (size_t i = 0; i < got.size(); ++i)
    if (got[i] != w[i]) {
      ++n;
      first = std::min(first, i);
    }
  if (n == 0) return "";
  const size_t per_eye = static_cast<size_t>(want.width) * static_cast<size_t>(want.height);
  return std::to_string(n) + " differ, first at eye " + std::to_string(first / per_eye) + " x " +
         std::to_string(first % static_cast<size_t>(want.width)) + " y " +
         std::to_string((first % per_eye) / static_cast<size_t>(want.width)) + ": " + std::to_string(got[first]) +
         " instead of " + std::to_string(w[first]);
}

void expect_same_as_functional(scm::Fidelity level, const dp::ArpConfig& c, int frames) {
  MemoryPair mem(c.memory, c.timing.eyes);
  const dp::OrientationStream o = fast_turn(c, 1, frames);
  stage::TimedInputs in = inputs(c, mem.ref, o, 1, frames);
  const auto want = functional_frames(in);
  in.memories = &mem.timed;
  scm::TimedResult res;
  const auto got = run_level(level, in, &res);
  ASSERT_EQ(got.size(), want.size());
  for (const auto& [f, w] : want) {
    ASSERT_TRUE(got.count(f)) << "frame " << f;
    const auto& g = got.at(f);
    EXPECT_EQ(first_difference(g.frame.pixels, w.frame), "") << "frame " << f << " pixels differ";
    EXPECT_EQ(first_difference(g.frame.photon_ps, w.frame, true), "") << "frame " << f << " photon times differ";
    EXPECT_EQ(g.report.latency_min_ps, w.report.latency_min_ps);
    EXPECT_EQ(g.report.latency_median_ps, w.report.latency_median_ps);
    EXPECT_EQ(g.report.latency_max_ps, w.report.latency_max_ps);
    EXPECT_EQ(g.report.underflows, 0);
  }
  EXPECT_EQ(res.underflows, 0);
  EXPECT_EQ(res.issue_stalls, 0);
  if (level == scm::Fidelity::Detailed || level == scm::Fidelity::Cycle) {
    // Unstalled, every stage takes exactly its configured latency.
    for (int s = 0; s + 1 < dp::kStageCount; ++s) {
      EXPECT_EQ(res.stages[static_cast<size_t>(s)].min_cycles, c.timed.stage[static_cast<size_t>(s)].latency_cycles) << s;
      EXPECT_EQ(res.stages[static_cast<size_t>(s)].max_cycles, c.timed.stage[static_cast<size_t>(s)].latency_cycles) << s;
    }
    // The slack waits in the scan-out FIFO and nowhere else.
    ASSERT_EQ(res.fifos.size(), 7u);
    EXPECT_EQ(res.fifos.back().second.max_occupancy, c.timed.issue_slack_cycles + 1);
    EXPECT_EQ(res.fifos.back().second.blocked_writes, 0);
  }
}

}  // namespace

class LevelsAgree : public ::testing::TestWithParam<std::tuple<scm::Fidelity, std::string>> {};

TEST_P(LevelsAgree, FramesPhotonTimesAndLatenciesEqualTheFunctionalModel) {
  const auto [level, v] = GetParam();
  expect_same_as_functional(level, variant(v), v == "interlaced_mono" ? 2 : 3);
}

INSTANTIATE_TEST_SUITE_P(
    TimedLevels, LevelsAgree,
    ::testing::Combine(::testing::Values(scm::Fidelity::Detailed, scm::Fidelity::Cycle, scm::Fidelity::LooselyTimed),
                       ::testing::Values("default", "per_pixel_latch", "per_frame_nearest_exact", "side_by_side",
                                         "interlaced_mono", "deep_narrow")),
    [](const auto& p) { return scm::to_string(std::get<0>(p.param)) + "_" + std::get<1>(p.param); });

// Host writes: the port's timing equals the plan, the image shows from the
// frame after the vertical blank that follows the commit, at every level.
class HostWrites : public ::testing::TestWithParam<scm::Fidelity> {};

TEST_P(HostWrites, CommitSwapsAtTheNextVerticalBlankAndFramesMatch) {
  dp::ArpConfig c = small_config();
  c.timed.host_clock_hz = 3'000'000;
  c.timed.host_texels_per_cycle = 2;
  const dp::VideoTiming t(c.timing);
  MemoryPair mem(c.memory, 2);
  const auto still = dp::OrientationStream::constant(dp::from_yaw_pitch_roll_deg(0, 0, 0));
  stage::TimedInputs in = inputs(c, mem.ref, still, 0, 4);
  // Job 0: memory 1 of eye 0, a near red square over the -Z face, started mid-frame 0.
  // Job 1: the same memory again (waits for job 0's swap), cleared: the square goes away.
  stage::HostWriteJob j0;
  j0.start_ps = t.cycles_to_ps(t.frame_start_cycle(0) + 5000);
  j0.eye = 0;
  j0.memory = 1;
  for (int y = 16; y < 48; ++y)
    for (int x = 16; x < 48; ++x) j0.texels.push_back({5, static_cast<uint16_t>(x), static_cast<uint16_t>(y), mem.ref.format().pack_rgb8(255, 0, 0), 10});
  stage::HostWriteJob j1 = j0;
  j1.texels.clear();
  j1.clear_first = true;
  j1.start_ps = j0.start_ps + 1;
  in.host_jobs = {j0, j1};

  const auto plan = stage::plan_host_jobs(in.host_jobs, c);
  // 1024 texels at 2 per 3 MHz clock: 512 clocks, 170.7 us -- inside frame 0's scan.
  EXPECT_EQ(plan[0].swap_frame, 0);
  EXPECT_GT(plan[1].start_ps, plan[0].swap_ps);  // waited for the swap
  EXPECT_EQ(plan[1].swap_frame, 1);

  in.memories = &mem.ref;
  const auto want = functional_frames(in);
  in.memories = &mem.timed;
  scm::TimedResult res;
  const auto got = run_level(GetParam(), in, &res);
  ASSERT_EQ(res.host_jobs.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(res.host_jobs[i].start_ps, plan[i].start_ps) << i;
    EXPECT_EQ(res.host_jobs[i].commit_ps, plan[i].commit_ps) << i;
    EXPECT_EQ(res.host_jobs[i].swap_ps, plan[i].swap_ps) << i;
  }
  EXPECT_EQ(res.swaps, 2);
  for (const auto& [f, w] : want) {
    EXPECT_EQ(got.at(f).frame.pixels, w.frame.pixels) << "frame " << f;
  }
  // Looking ahead (-Z), the square shows in frame 1 only, in eye 0 only.
  auto red_in_middle = [](const HmdFrame& fr, int eye) { return fr.channel(eye, 80, 60, 0) > 200 && fr.channel(eye, 80, 60, 1) < 40; };
  EXPECT_FALSE(red_in_middle(got.at(0).frame, 0));
  EXPECT_TRUE(red_in_middle(got.at(1).frame, 0));
  EXPECT_FALSE(red_in_middle(got.at(1).frame, 1));
  EXPECT_FALSE(red_in_middle(got.at(2).frame, 0));
}

INSTANTIATE_TEST_SUITE_P(TimedLevels, HostWrites,
                         ::testing::Values(scm::Fidelity::Detailed, scm::Fidelity::Cycle, scm::Fidelity::LooselyTimed),
                         [](const auto& p) { return scm::to_string(p.param); });

// Backpressure: the anti-aliasing filter stalls for 40 clocks in the middle of
// a line. The FIFOs behind it fill, the issue backs up, pixels miss their
// slots: underflows are counted at scan-out and shown, the late pixels dropped
// and counted; photon times stay on the scan, and the next frame is exact again.
class Backpressure : public ::testing::TestWithParam<scm::Fidelity> {};

TEST_P(Backpressure, StalledStageFillsFifosThenUnderflowsAreCounted) {
  const dp::ArpConfig c = small_config();
  const dp::VideoTiming t(c.timing);
  MemoryPair mem(c.memory, 2);
  const auto still = dp::OrientationStream::constant(dp::from_yaw_pitch_roll_deg(10, 5, 0));
  stage::TimedInputs in = inputs(c, mem.ref, still, 0, 2);
  const auto want = functional_frames(in);
  in.memories = &mem.timed;
  const int64_t stall_at = t.pixel_cycle(0, 0, 40, 30);
  const int64_t stall_len = 40;
  in.stalls = {{dp::Stage::Filter, stall_at, stall_len}};
  scm::TimedResult res;
  const auto got = run_level(GetParam(), in, &res);

  // Every FIFO up to the filter's input ran full.
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(res.fifos[i].second.max_occupancy, c.timed.fifo_depth) << res.fifos[i].first;
    EXPECT_GT(res.fifos[i].second.full_cycles, 0) << res.fifos[i].first;
  }
  EXPECT_GT(res.issue_stalls, 0);
  EXPECT_EQ(res.stages[static_cast<size_t>(dp::Stage::Filter)].forced_stall_cycles, stall_len);
  // A 40-clock stall leaves the pipeline 40 pixels behind. Scan-out pops one
  // pixel a clock, so the rest of line 30 misses its slots; in the horizontal
  // blanking the late pixels are dropped and line 31 is on time again.
  const stage::FrameReport& r0 = got.at(0).report;
  EXPECT_GT(r0.underflows, 0);
  EXPECT_EQ(r0.underflows, res.underflows);
  EXPECT_GE(r0.late_discarded, stall_len - c.timed.issue_slack_cycles - 1);
  EXPECT_LE(r0.underflows, c.timing.h_active - 40);
  // The underflowed pixels are exactly the ones that differ, all on line 30 after the stall, in the underflow colour.
  const uint32_t bad = stage::underflow_color(c.pipeline.display_bits);
  int64_t differ = 0;
  const HmdFrame& g0 = got.at(0).frame;
  const HmdFrame& w0 = want.at(0).frame;
  for (int e = 0; e < 2; ++e)
    for (int y = 0; y < g0.height; ++y)
      for (int x = 0; x < g0.width; ++x)
        if (g0.at(e, x, y) != w0.at(e, x, y)) {
          ++differ;
          EXPECT_EQ(g0.at(e, x, y), bad);
          EXPECT_EQ(y, 30);
          EXPECT_GE(x, 40);
        }
  EXPECT_EQ(differ, 2 * r0.underflows);  // both eyes of each slot
  EXPECT_EQ(got.at(0).frame.photon_ps, want.at(0).frame.photon_ps);
  EXPECT_EQ(got.at(1).frame.pixels, want.at(1).frame.pixels);
  EXPECT_EQ(got.at(1).report.underflows, 0);
}

INSTANTIATE_TEST_SUITE_P(TimedLevels, Backpressure, ::testing::Values(scm::Fidelity::Detailed, scm::Fidelity::Cycle),
                         [](const auto& p) { return scm::to_string(p.param); });

// Configurations the hardware cannot meet are refused before simulating.
TEST(TimedLevels, ImpossibleHardwareIsRefusedBeforeSimulation) {
  auto refused = [](dp::ArpConfig c, const std::string& key) {
    const auto issues = dp::validate_timed(c);
    EXPECT_FALSE(issues.empty()) << key;
    if (!issues.empty()) {
      EXPECT_EQ(issues.front().key, key);
    }
    dp::DisplayMemorySet mem(c.memory.count <= 16 && c.memory.count >= 1 ? c.memory : dp::MemoryConfig{}, c.timing.eyes);
    const auto o = dp::OrientationStream::constant(dp::Quat{});
    stage::TimedInputs in = inputs(c, mem, o, 0, 1);
    scm::TimedRunOptions opt;
    opt.fidelity = scm::Fidelity::Detailed;
    if (mem.count() == c.memory.count) {
      EXPECT_THROW(scm::run_timed(in, opt), InputError) << key;
    }
  };
  dp::ArpConfig c = small_config();
  c.timing.pixel_clock_hz = 80'000'000;  // 12.5 ns: the address generator's 60 ns over 4 stages needs 15 ns
  refused(c, "timed.address_latency");
  c = small_config();
  c.timed.fifo_depth = 0;
  refused(c, "timed.fifo_depth");
  c = small_config();
  c.memory.count = 9;
  refused(c, "memory.count");
  c = small_config();
  c.timed.issue_slack_cycles = 2000;
  c.timed.fifo_depth = 2002;
  refused(c, "timed.issue_slack_cycles");
  c = small_config();
  c.timed.issue_slack_cycles = 4;
  c.timed.fifo_depth = 5;
  refused(c, "timed.fifo_depth");
}
