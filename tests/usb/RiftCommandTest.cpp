// `arpsim tracker list`, `tracker record`, `run --live usb` against emulated
// Rift DK1s (umockdev; see RiftEmulator.hpp): the commands find the device,
// record a trace that replays into the pipeline, and survive an unplug.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "../LiveWindow.hpp"
#include "../TestSupport.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "RiftEmulator.hpp"
#include "tracker/Fusion.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/TraceFile.hpp"

using namespace arp;
using namespace arp::tracker;

namespace {

using test::yaw_90;

using arp::test::read_text;

// Samples 1 ms apart on the device; on the host's timeline a step is shorter while the clock sheds the
// first report's latency (DeviceClock's lower envelope: each report that arrived sooner than any before
// moves the timeline earlier), and the steps shed add up to less than the lead tolerance. Longer only by
// the host/device rate skew, once 10 s of device time allow estimating it (a slow machine's run can reach
// that): each step by 0.1 % at most, and the one step where the estimate first applies by 20 ms.
void expect_device_steps(const std::vector<tracker::PoseSample>& trace) {
  int64_t shed = 0;
  int longer = 0;
  for (size_t i = 1; i < trace.size(); ++i) {
    const int64_t step = trace[i].time_ps - trace[i - 1].time_ps;
    ASSERT_GT(step, 0) << i;
    if (step > 1'001'000'000) {
      ++longer;
      ASSERT_LE(step, 21'000'000'000) << i;
    }
    shed += std::max<int64_t>(0, 1'000'000'000 - step);
  }
  EXPECT_LE(longer, 1);
  EXPECT_LT(shed, 250'000'000'000);
}


}  // namespace

TEST(RiftCommand, TrackerListAndRecordFromTheCommandLine) {
  const auto truth = yaw_90(6.0);
  test::RiftEmulator dk1(RiftModel::DK1, truth);
  arp::test::TempDir d;
  const auto list = arp::test::run_command(arp::test::kArpsim + " tracker list");
  EXPECT_EQ(list.status, 0) << list.output;
  EXPECT_NE(list.output.find("Oculus Rift DK1"), std::string::npos) << list.output;
  const auto rec = arp::test::run_command(arp::test::kArpsim + " tracker record -q --seconds 0.5 " + d.file("head.csv"));
  ASSERT_EQ(rec.status, 0) << rec.output;
  const auto trace = read_trace_csv(d.file("head.csv"));
  // How many samples 0.5 s of wall time holds depends on the machine's pace (a CI run had 243 of ~500);
  // what must hold at any pace: the device's samples, consecutive, following the truth.
  ASSERT_GT(trace.size(), 50u);
  ASSERT_NO_FATAL_FAILURE(expect_device_steps(trace));
  EXPECT_LT(angle_between_deg(trace.back().orientation, truth[trace.size()].orientation), 0.5);
  // The recording replays into the pipeline.
  const auto run = arp::test::run_command(arp::test::kArpsim + " run -q --frames 2 --every 0 --trace " + d.file("head.csv") +
                                          " --set display.h_active=64 --set display.v_active=48");
  EXPECT_EQ(run.status, 0) << run.output;
}

TEST(RiftCommand, NoDeviceGivesAClearAnswer) {
  const auto list = arp::test::run_command(arp::test::kArpsim + " tracker list");
  EXPECT_NE(list.output.find("no Oculus Rift DK1/DK2 found"), std::string::npos) << list.output;
}

// Unplugged in the middle of a recording and of a live run: both go on, the
// events are reported, and everything received before and after is kept.
TEST(RiftCommand, RecordAndLiveRunSurviveAnUnplug) {
  const auto truth = yaw_90(20.0);
  test::RiftEmulator dk1(RiftModel::DK1, truth);
  arp::test::TempDir d;
  // Unplugs once the child has streamed 200 reports (however long it takes to start), for 300 ms.
  int64_t sent_before_unplug = 0;  // reports the child was sent before the last unplug (one sample each)
  auto unplug_for_a_while = [&dk1, &sent_before_unplug] {
    const int64_t base = dk1.reports_sent();
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (dk1.reports_sent() < base + 200 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    dk1.unplug();
    sent_before_unplug = dk1.reports_sent() - base;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    dk1.replug();
  };
  // An arpsim command, the tracker unplugged for a while under it.
  auto run_across_an_unplug = [&](const std::string& args, const std::string& prefix = "") {
    arp::test::CommandResult r;
    std::thread child([&] { r = arp::test::run_command(prefix + arp::test::kArpsim + " " + args); });
    unplug_for_a_while();
    child.join();
    return r;
  };
  {
    const auto rec = run_across_an_unplug("tracker record -q --seconds 2.5 " + d.file("gap.csv"));
    ASSERT_EQ(rec.status, 0) << rec.output;
    EXPECT_NE(rec.output.find("disconnected"), std::string::npos) << rec.output;
    EXPECT_NE(rec.output.find("reconnected"), std::string::npos) << rec.output;
    EXPECT_NE(rec.output.find("1 disconnects, 1 reconnects"), std::string::npos) << rec.output;
    const auto trace = read_trace_csv(d.file("gap.csv"));
    // Before the unplug and after the replug, with a gap of about 300 ms in between (counts that hold at
    // any pace: the unplug waits for 200 reports; the recording lasts 2.5 s, the replug comes 0.3 s after).
    int64_t gap = 0;
    size_t gap_at = 0;
    for (size_t i = 1; i < trace.size(); ++i)
      if (trace[i].time_ps - trace[i - 1].time_ps > gap) {
        gap = trace[i].time_ps - trace[i - 1].time_ps;
        gap_at = i;
      }
    EXPECT_GT(gap, 200'000'000'000);
    EXPECT_GE(gap_at, 150u);
    EXPECT_GT(trace.size() - gap_at, 100u);
  }
  {
    dk1.replug();
    // 90 frames of the default display: 1.5 s at its 60 Hz pace.
    const auto run = run_across_an_unplug("run -q --live usb --frames 90 --every 0 --report " + d.file("live.json"));
    ASSERT_EQ(run.status, 0) << run.output;
    const std::string rep = read_text(d.file("live.json"));
    const size_t live_at = rep.find("\"live\"");
    ASSERT_NE(live_at, std::string::npos);
    EXPECT_NE(rep.find("\"device_disconnects\": 1"), std::string::npos) << rep.substr(live_at, 400) << run.output;
    EXPECT_NE(rep.find("\"device_reconnects\": 1"), std::string::npos);
    EXPECT_NE(rep.find("live Oculus Rift DK1 (USB)"), std::string::npos);
    EXPECT_NE(rep.find("\"connected_at_end\": true"), std::string::npos);
    EXPECT_NE(run.output.find("live input"), std::string::npos) << run.output;
  }
  {
    // The live window the same way: the events said, the frames shown to the end, the poses from after the
    // replug taken (the unplug may come before the loop's first frame or during it, as the window opens).
    dk1.replug();
    const auto live = run_across_an_unplug("live -q --live usb --seconds 1.5 --record-live " + d.file("window.csv"), arp::test::kXvfbRun);
    ASSERT_EQ(live.status, 0) << live.output;
    EXPECT_NE(live.output.find("] disconnected"), std::string::npos) << live.output;
    EXPECT_NE(live.output.find("] reconnected"), std::string::npos) << live.output;
    EXPECT_NE(live.output.find("90 frames of Oculus Rift DK1"), std::string::npos) << live.output;
    // The replug's samples were received and taken, not the pose held: everything past the samples the
    // child was sent before the unplug came after the replug, and a held pose takes none of them. How many
    // depends on the pace: the loop runs about 0.8 s after the replug, but a CI run under ASan, with the
    // other test job, Xvfb and 163 ms renders on 2 cores, starved the emulator to ~110 samples a second
    // (88 taken after the replug). A margin of 10 holds at any pace that lets the events above be seen.
    // (Not their times: a starved emulator's samples fall behind the loop's clock, and the last one taken
    // can be from well before the end.)
    long long taken = -1, before = -1;
    const size_t at = live.output.find("tracker samples taken");
    ASSERT_NE(at, std::string::npos) << live.output;
    ASSERT_EQ(std::sscanf(live.output.c_str() + live.output.rfind("arpsim live: ", at), "arpsim live: %lld tracker samples taken (%lld", &taken, &before), 2)
        << live.output;
    EXPECT_GT(taken + before, sent_before_unplug + 10) << live.output;
    EXPECT_EQ(static_cast<long long>(read_trace_csv(d.file("window.csv")).size()), taken);
  }
}

namespace {
// The integer after "key": in a pretty-printed JSON report (-1 if absent).
// The first integer `key` in `text` (after `after`, when given).
int64_t json_int(const std::string& text, const std::string& key, const std::string& after = "") {
  const size_t from = after.empty() ? 0 : text.find("\"" + after + "\"");
  if (from == std::string::npos) return -1;
  const size_t at = text.find("\"" + key + "\": ", from);
  return at == std::string::npos ? -1 : std::stoll(text.substr(at + key.size() + 4));
}
double json_double(const std::string& text, const std::string& key) {
  const size_t at = text.find("\"" + key + "\": ");
  return at == std::string::npos ? -1.0 : std::stod(text.substr(at + key.size() + 4));
}

// A live run's report: its "live" object (empty if none) and the counts every sample is accounted by.
struct LiveCounts {
  std::string rep;
  int64_t taken = -1, before = -1, out_of_order = -1, after = -1, sent = -1, dropped = -1;
};
LiveCounts read_live_report(const std::string& path) {
  const std::string all = read_text(path);
  const size_t at = all.find("\"live\"");
  if (at == std::string::npos) return {};
  LiveCounts c;
  c.rep = all.substr(at);
  c.taken = json_int(c.rep, "samples");
  c.before = json_int(c.rep, "samples_before_start");
  c.out_of_order = json_int(c.rep, "samples_out_of_order");
  c.after = json_int(c.rep, "samples_after_end");
  c.sent = json_int(c.rep, "device_samples");
  c.dropped = json_int(c.rep, "device_dropped_unconsumed");
  return c;
}

// What the pipeline took (--record-live), each the device's next sample: sample j of the device fused is the
// motion after j + 1 ms, the first taken being the device's sample `before` (the last received before the start).
void expect_took_the_device_in_order(const std::vector<tracker::PoseSample>& took, int64_t before,
                                     const std::vector<tracker::PoseSample>& truth) {
  for (size_t i = 0; i < took.size(); ++i) {
    const size_t j = static_cast<size_t>(before) + i + 1;
    ASSERT_LT(j, truth.size());
    // (0.01 deg: measured 1.3e-4; one sample off is 0.09 deg at 90 deg/s)
    ASSERT_LT(angle_between_deg(took[i].orientation, truth[j].orientation), 0.01) << i;
  }
}
}  // namespace

// A run slower than the display (the functional model at its default size renders ~15 frames a second
// here against the display's 60): every frame is late, yet it takes what the device sent -- before, a late
// frame took nothing (0 of 1001 samples reached the pipeline).
TEST(RiftCommand, ARunSlowerThanTheDisplayTakesEverySample) {
  const auto truth = yaw_90(30.0);
  test::RiftEmulator dk1(RiftModel::DK1, truth);
  arp::test::TempDir d;
  const auto run = arp::test::run_command(arp::test::kArpsim + " run -q --live usb --frames 20 --every 0 --report " +
                                          d.file("slow.json") + " --record-live " + d.file("taken.csv"));
  ASSERT_EQ(run.status, 0) << run.output;
  const LiveCounts c = read_live_report(d.file("slow.json"));
  ASSERT_FALSE(c.rep.empty()) << read_text(d.file("slow.json"));
  const std::string& rep = c.rep;
  const int64_t taken = c.taken, before = c.before, after = c.after, sent = c.sent, dropped = c.dropped;
  ASSERT_GT(sent, 100) << rep.substr(0, 800);
  EXPECT_EQ(dropped, 0);
  EXPECT_EQ(c.out_of_order, 0);  // the device's clock never steps back, nor does the stream's timeline
  EXPECT_GE(taken + before + c.out_of_order + after + dropped, sent);  // every sample accounted for
  // What the pipeline took, as it took it (--record-live): every one, in the device's order, each the
  // device's next sample -- sample j of the device fused is the motion after j + 1 ms, the first taken
  // being the device's sample `before` -- on steps of its 1 ms (less while the clock sheds the first
  // report's latency).
  ASSERT_GT(taken, 0) << rep << "\n" << run.output;
  const auto took = read_trace_csv(d.file("taken.csv"));
  ASSERT_EQ(static_cast<int64_t>(took.size()), taken);
  EXPECT_EQ(json_int(rep, "samples", "recorded"), taken);
  ASSERT_NO_FATAL_FAILURE(expect_device_steps(took));
  ASSERT_NO_FATAL_FAILURE(expect_took_the_device_in_order(took, before, truth));
  // Received during the run, not only by the drain after its end: what is left for the drain is what the
  // stream fused during the last frame and the report (before, a late frame took nothing, and the drain
  // would hold everything fused after the first frame). Holds at any pace: a starved stream fuses late,
  // but its samples still come in frame by frame.
  EXPECT_LT(after * 4, taken + before + after) << "taken " << taken << ", before the start " << before << ", after the end " << after;
  // How far behind the tracker it fell is reported, and said when it is more than a frame (whatever the pace:
  // a machine that keeps up reports less than a frame and no note).
  const double behind = json_double(rep, "behind_max_s");
  ASSERT_GE(behind, 0.0) << rep.substr(0, 800);
  EXPECT_GE(json_double(rep, "behind_max_s"), json_double(rep, "behind_at_end_s"));
  const bool said = run.output.find("behind the tracker; every sample was still taken") != std::string::npos;
  if (std::abs(behind * 60.0 - 1.0) > 0.05) {  // the default display's frame is 1/60 s (not judged right at the edge)
    EXPECT_EQ(said, behind * 60.0 >= 1.0) << "behind " << behind << " s\n" << run.output;
  }
}

// A transport slower than the device (what the emulator is when starved of CPU: a loaded CI machine's
// run was handed 1 300 samples in 1.9 s): the device's time falls ever further behind the host's, and
// what arrives during the run was sampled, on the device's clock, before the run began. It is still the
// run's to take: judged by arrival, the last sample received before the start is the pose at the start,
// and the next are placed after it by the device's time. Before, the run took nothing: every sample was
// counted as sent before its start.
TEST(RiftCommand, ATransportSlowerThanTheDeviceStillFeedsTheRun) {
  const auto truth = yaw_90(30.0);
  test::RiftEmulator dk1(RiftModel::DK1, truth);
  constexpr int kPerSecond = 100;  // a tenth of the device's rate
  dk1.slow_transport(kPerSecond);
  arp::test::TempDir d;
  constexpr int kFrames = 30;
  // (A 64 x 48 display at 60 Hz: 224 x 93 clocks a frame.)
  const auto run = arp::test::run_command(arp::test::kArpsim + " run -q --live usb --frames " + std::to_string(kFrames) +
                                          " --every 0 --set display.h_active=64 --set display.v_active=48 --set display.pixel_clock_hz=1249920 --report " +
                                          d.file("r.json") + " --record-live " + d.file("taken.csv"));
  ASSERT_EQ(run.status, 0) << run.output;
  const LiveCounts c = read_live_report(d.file("r.json"));
  ASSERT_FALSE(c.rep.empty()) << read_text(d.file("r.json"));
  const std::string& rep = c.rep;
  const int64_t taken = c.taken, before = c.before;
  EXPECT_EQ(c.out_of_order, 0) << rep;
  EXPECT_GE(c.taken + c.before + c.after + c.dropped, c.sent) << rep;  // (the device's count is read before the last drain)
  // A live run goes at the display's pace or slower: it takes what arrives for kFrames / 60 s at least, up to
  // kPerSecond a second -- 50 samples, fewer from an emulator starved further. A fifth of that is the bound:
  // the old rule took none (measured: 0 here, 0 of 1 300 on the loaded CI machine).
  ASSERT_GE(taken, kPerSecond * kFrames / 60 / 5) << rep << run.output;
  const auto took = read_trace_csv(d.file("taken.csv"));
  ASSERT_EQ(static_cast<int64_t>(took.size()), taken);
  // In the device's order from the last received before the start, which is at the start; then on the
  // device's 1 ms steps (less while the clock sheds the first report's latency).
  ASSERT_NO_FATAL_FAILURE(expect_device_steps(took));
  EXPECT_EQ(took[0].time_ps, 0);
  EXPECT_GT(took[1].time_ps, 0);
  EXPECT_LE(took[1].time_ps, 1'000'000'000);
  ASSERT_NO_FATAL_FAILURE(expect_took_the_device_in_order(took, before, truth));
}

// A live run holds what it took from a second and two frames behind each frame, not the whole run (a DK1's
// 1 kHz held whole grows by 144 MB an hour; until 2026-11-28 it was held whole). A 64 x 48 display keeps the
// display's pace, so the samples ahead of a frame are the frame's own.
TEST(RiftCommand, ALiveRunHoldsASecondOfSamplesBehindItsFrame) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(30.0));
  arp::test::TempDir d;
  const auto run = arp::test::run_command(arp::test::kArpsim + " run -q --live usb --frames 240 --every 0 --set display.h_active=64 "
                                          "--set display.v_active=48 --set display.pixel_clock_hz=1249920 --report " + d.file("r.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  const LiveCounts c = read_live_report(d.file("r.json"));
  ASSERT_FALSE(c.rep.empty());
  const int64_t held = json_int(c.rep, "samples_held_max");
  // About a second and four frames at the device's 1 kHz, plus what runs ahead of the frames: what arrived
  // while the run was behind the tracker, and what a starved emulator handed over late (sampled before the
  // start but received after it, it is placed after the start by the device's time: the timeline is fixed by
  // arrival). That last part cannot be told from the report (CI under ASan: 1 558 held of 4 453 taken, 1 473
  // of 3 881), so the bound is half of what was taken: the trim keeps a second of a 4 s run, holding all of it
  // keeps everything (4 050 here).
  EXPECT_GT(held, 0) << c.rep;
  EXPECT_LT(held * 2, c.taken) << c.rep;
  // (At half the device's rate, as a loaded machine's emulator has run, still 2 000 taken.)
  EXPECT_GT(c.taken, 1500) << c.rep;
}

// `arpsim live` with the tracker on USB, in its window under Xvfb: the window shows the pipeline's frame for
// the motion the tracker sent. What the loop took is recorded (--record-live) and replays in `run --trace`:
// the window's last frame, outside the overlay, is that run's frame pixel for pixel (the recording ends with
// the last samples taken before that frame was rendered, so it holds exactly what the frame saw, at any
// pace). And it is the head turned, not the still head's frame.
TEST(RiftCommand, TheLiveWindowShowsTheTrackersMotionAndItsRecordingReplays) {
  const auto truth = yaw_90(30.0);
  test::RiftEmulator dk1(RiftModel::DK1, truth);
  arp::test::TempDir d;
  const std::string& arpsim = arp::test::kArpsim;
  const auto live = arp::test::run_command(arp::test::kXvfbRun + arpsim + " live -q --live usb --seconds 0.5 --screenshot " +
                                           d.file("shot.png") + " --record-live " + d.file("took.csv"));
  ASSERT_EQ(live.status, 0) << live.output;
  EXPECT_NE(live.output.find("30 frames of Oculus Rift DK1"), std::string::npos) << live.output;
  const auto took = read_trace_csv(d.file("took.csv"));
  ASSERT_GT(took.size(), 10u) << live.output;
  EXPECT_NE(live.output.find(std::to_string(took.size()) + " tracker samples taken"), std::string::npos) << live.output;
  EXPECT_EQ(took[0].time_ps, 0);  // the pose at the start: the last received before it
  ASSERT_NO_FATAL_FAILURE(expect_device_steps(took));
  // (--every 29: frames 0 and 29)
  const auto replay = arp::test::run_command(arpsim + " run -q --fidelity functional --frames 30 --every 29 --trace " + d.file("took.csv") +
                                             " --out-dir " + d.file("replay"));
  ASSERT_EQ(replay.status, 0) << replay.output;
  const auto still = arp::test::run_command(arpsim + " frame --frame 29 --out " + d.file("still.png"));
  ASSERT_EQ(still.status, 0) << still.output;
  const host::RgbImage shot = host::read_rgb8(d.file("shot.png"));
  const auto same = arp::test::compare_outside_overlay(shot, host::read_rgb8(d.file("replay/frame_000029.png")));
  EXPECT_GT(same.text, 1000);  // the overlay is there
  EXPECT_EQ(same.differ, 0);
  // Turned: the calibration pattern has moved under most of the window (a half turn of a degree moves most).
  const auto moved = arp::test::compare_outside_overlay(shot, host::read_rgb8(d.file("still.png")));
  EXPECT_GT(moved.differ, shot.width * shot.height / 4) << "the window shows the still head";
}

// Two trackers on the command line: the list tells them apart and says what to
// pass; a recording or a live run without a choice is refused, listing them.
TEST(RiftCommand, TwoTrackersAreListedAndOneIsChosen) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(20.0), test::RiftEmulator::Layout::Rift, {2, "DK1-A"});
  test::RiftEmulator dk2(RiftModel::DK2, yaw_90(20.0), test::RiftEmulator::Layout::Rift, {3, "DK2-B"});
  const std::string& arpsim = arp::test::kArpsim;
  arp::test::TempDir d;
  const auto list = arp::test::run_command(arpsim + " tracker list");
  EXPECT_EQ(list.status, 0) << list.output;
  EXPECT_NE(list.output.find("Oculus Rift DK1 bus 001 address 002 serial DK1-A  ready  (--device DK1-A)\n"
                             "Oculus Rift DK2 bus 001 address 003 serial DK2-B  ready  (--device DK2-B)"),
            std::string::npos)
      << list.output;
  const auto unchosen = arp::test::run_command(arpsim + " tracker record -q --seconds 0.2 " + d.file("a.csv"));
  EXPECT_EQ(unchosen.status, 2) << "a choice to make is a usage error, as in run --live usb: " << unchosen.output;
  EXPECT_NE(unchosen.output.find("--device: 2 trackers attached"), std::string::npos) << unchosen.output;
  const auto nomatch = arp::test::run_command(arpsim + " tracker record -q --seconds 0.2 --device NOMATCH " + d.file("a.csv"));
  EXPECT_EQ(nomatch.status, 2) << nomatch.output;
  EXPECT_NE(nomatch.output.find("--device: NOMATCH: no tracker is 'NOMATCH'"), std::string::npos) << nomatch.output;
  EXPECT_FALSE(std::filesystem::exists(d.file("a.csv")));
  const auto chosen = arp::test::run_command(arpsim + " tracker record -q --seconds 0.3 --device DK2-B " + d.file("b.csv"));
  ASSERT_EQ(chosen.status, 0) << chosen.output;
  EXPECT_NE(chosen.output.find("DK2"), std::string::npos) << chosen.output;
  EXPECT_GT(read_trace_csv(d.file("b.csv")).size(), 10u);
  arp::test::expect_refused(arpsim + " ",
                            {
                                {"run -q --frames 1 --device DK1-A", "--device: DK1-A: chooses the tracker of --live usb"},
                                {"run -q --frames 1 --live usb", "--device: 2 trackers attached"},
                                {"run -q --frames 1 --live usb --device 9:9", "--device: 9:9: no tracker is '9:9'"},
                            },
                            " --every 0");
}

// --record-live is for live input, and a path it cannot write is said before the run, naming it; nothing
// is left behind.
TEST(RiftCommand, RecordLiveIsCheckedBeforeTheRun) {
  arp::test::TempDir d;
  const auto alone = arp::test::run_command(arp::test::kArpsim + " run -q --frames 2 --record-live " + d.file("t.csv"));
  EXPECT_EQ(alone.status, 2) << alone.output;
  EXPECT_NE(alone.output.find("--record-live"), std::string::npos) << alone.output;
  EXPECT_NE(alone.output.find("use it with --live usb"), std::string::npos) << alone.output;
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(30.0));
  const auto nowhere = arp::test::run_command(arp::test::kArpsim + " run -q --live usb --frames 2 --csv " + d.file("f.csv") +
                                              " --record-live " + d.file("no/such/folder/t.csv"));
  EXPECT_EQ(nowhere.status, 2) << nowhere.output;
  EXPECT_NE(nowhere.output.find("no/such/folder/t.csv"), std::string::npos) << nowhere.output;
  // Said before the run: the run's own outputs were not written.
  EXPECT_FALSE(std::filesystem::exists(d.file("f.csv")));
  // Nor may it overwrite another of the run's files.
  const auto clash = arp::test::run_command(arp::test::kArpsim + " run -q --frames 2 --live usb --report " + d.file("r.json") +
                                            " --record-live " + d.file("r.json"));
  EXPECT_EQ(clash.status, 2) << clash.output;
  EXPECT_NE(clash.output.find("--record-live"), std::string::npos) << clash.output;
  EXPECT_TRUE(std::filesystem::is_empty(d.path())) << "something was left in " << d.path();
}
