// The libusb streaming driver end to end against emulated DK1 and DK2 IMUs
// (umockdev; see RiftEmulator.hpp): the kernel driver detached, interface 0
// claimed, config and keep-alive feature reports byte-exact, reports decoded
// and fused into the synthetic motion across the device counter's wrap, a
// malformed report counted and skipped, the stream surviving an unplug (last
// pose held, event reported) and resuming after the replug, and
// `arpsim tracker record` writing a trace from the emulated device.
#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "../TestSupport.hpp"
#include "RiftEmulator.hpp"
#include "tracker/Fusion.hpp"
#include "tracker/RiftProtocol.hpp"
#include "tracker/RiftStream.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/TraceFile.hpp"
#include "tracker/UsbTrackers.hpp"

using namespace arp;
using namespace arp::tracker;

namespace {

using test::yaw_90;

// Polls for `seconds` of wall time, collecting poses.
void stream_for(RiftStream& r, double seconds, std::vector<PoseSample>& out) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) r.poll(5, out);
}

// Polls until `done` holds, or fails after `limit_s` of wall time (a bound for a stuck stream, not a pace).
template <class Done>
void stream_until(RiftStream& r, Done done, std::vector<PoseSample>& out, const char* what, double limit_s = 20) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (!done() && std::chrono::steady_clock::now() < until) r.poll(5, out);
  ASSERT_TRUE(done()) << "still waiting for " << what << " after " << limit_s << " s";
}

// Report k carries the motion's sample k (one sample a report): after n reports the orientation is the
// truth's sample n - 1 integrated over one more millisecond (the first step). Reports whose samples
// were not fused (malformed, stale) are motion lost; `trail_deg` is what the test expects that to cost.
void expect_fused_motion(const RiftStream& r, const std::vector<PoseSample>& truth, double trail_deg = 0) {
  const RiftStream::Snapshot now = r.snapshot();  // the count and the pose together: the pump fuses on
  const int64_t n = now.stats.samples + now.stats.malformed + now.stats.time_went_back;
  ASSERT_GT(n, 100);
  ASSERT_LT(static_cast<size_t>(n), truth.size());
  EXPECT_NEAR(angle_between_deg(now.last.orientation, truth[static_cast<size_t>(n)].orientation), trail_deg, 0.5) << n << " reports";
}

constexpr int64_t kMsPs = 1'000'000'000;

// Waits until the device has sent every report it owes by the test's clock, the stream has taken them
// all (decoded or refused) and has asked for more since (so its pump does its keep-alive check before
// it can take another: every step of the clock is seen). The wall-clock limit only bounds a stuck
// stream; it sets no pace.
// With `out` null nothing is taken from the stream (a consumer that does not poll).
void settle(const test::RiftEmulator& d, RiftStream& r, std::vector<PoseSample>* out, double limit_s = 20) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  for (;;) {
    const int64_t sent = d.reports_sent();
    const StreamStats st = r.stats();
    if (sent == d.reports_due() && st.reports + st.malformed == sent && d.host_drained()) return;
    ASSERT_LT(std::chrono::steady_clock::now(), until) << "device sent " << sent << " of " << d.reports_due() << ", stream took "
                                                       << st.reports + st.malformed;
    if (out) r.poll(1, *out);
    else std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

// Advances the test's clock `ms` milliseconds one at a time, settling before each step and after the last.
void drive(test::ManualClock& clock, const test::RiftEmulator& d, RiftStream& r, int64_t ms, std::vector<PoseSample>* out) {
  for (int64_t i = 0; i < ms; ++i) {
    ASSERT_NO_FATAL_FAILURE(settle(d, r, out));
    clock.advance_ps(kMsPs);
  }
  ASSERT_NO_FATAL_FAILURE(settle(d, r, out));
}

// Collects what the stream fused until `n` poses are in `out` (the pump may not have handed them over yet).
void collect(RiftStream& r, std::vector<PoseSample>& out, size_t n, double limit_s = 20) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (out.size() < n && std::chrono::steady_clock::now() < until) r.poll(5, out);
  ASSERT_GE(out.size(), n);
}

// An emulated device and a stream on one clock the test drives (opened by open(): a test may set the
// device's quirks first).
struct Driven {
  test::ManualClock clock;
  test::RiftEmulator device;
  RiftStream stream;
  Driven(RiftModel model, std::vector<PoseSample> truth, RiftStreamOptions o = {})
      : device(model, std::move(truth)), stream((o.host_clock = clock.function(), o)) {
    device.drive_by(clock);
  }
  bool open() {
    std::string err;
    const bool ok = stream.open(err);
    EXPECT_TRUE(ok) << err;
    return ok;
  }
  std::vector<PoseSample> poses;  // what drive() took
  void drive(int64_t ms, std::vector<PoseSample>* out) { ::drive(clock, device, stream, ms, out); }
  void drive(int64_t ms) { drive(ms, &poses); }
};

}  // namespace

// Driven by the test's clock (device and stream alike): every report the
// device sends in 1.2 s of its time arrives, across the 16-bit millisecond
// counter's wrap (after 536 reports), and is stamped exactly when it was sent
// -- sample k at k ms -- because the keep-alive was re-sent every 100 ms of
// that clock, well inside the device's 300 ms, whatever the machine's pace.
TEST(RiftStream, Dk1StreamsAcrossTheCounterWrapAndKeepsItsKeepAlive) {
  const auto truth = yaw_90(4.0);
  RiftStreamOptions o;
  o.keep_alive_ms = 300;        // the device stops 300 ms after the last keep-alive...
  o.keep_alive_resend_s = 0.1;  // ...so 1.2 s of streaming needs the re-sends
  Driven t(RiftModel::DK1, truth, o);
  test::RiftEmulator& dk1 = t.device;
  RiftStream& r = t.stream;
  ASSERT_TRUE(t.open());
  EXPECT_EQ(r.model(), RiftModel::DK1);
  EXPECT_TRUE(dk1.kernel_driver_detached());
  EXPECT_TRUE(dk1.interface_claimed());
  EXPECT_TRUE(r.stats().kernel_driver_detached);
  ASSERT_NO_FATAL_FAILURE(t.drive(1200));
  ASSERT_NO_FATAL_FAILURE(collect(r, t.poses, 1201));
  EXPECT_EQ(dk1.reports_sent(), 1201);  // the device never ran out of keep-alive
  EXPECT_TRUE(r.connected());
  EXPECT_EQ(r.stats().malformed, 0);
  EXPECT_EQ(r.stats().time_went_back, 0);
  EXPECT_EQ(r.stats().clock_reanchors, 0);
  ASSERT_EQ(t.poses.size(), 1201u);
  for (size_t k = 0; k < t.poses.size(); ++k) ASSERT_EQ(t.poses[k].time_ps, static_cast<int64_t>(k) * kMsPs) << k;
  expect_fused_motion(r, truth);
  // The config report first, then keep-alives, byte-exact: one at the start and one each 100 ms of the
  // clock (the stream checks between any two reports, so at the millisecond it is due or the next).
  // (The device records a keep-alive before the stream counts it: wait until both agree.)
  const auto agreed = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (static_cast<int64_t>(dk1.feature_reports().size()) != 1 + r.stats().keep_alives && std::chrono::steady_clock::now() < agreed)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const int64_t keep_alives = r.stats().keep_alives;
  EXPECT_GE(keep_alives, 12);
  EXPECT_LE(keep_alives, 13);
  const auto f = dk1.feature_reports();
  ASSERT_EQ(static_cast<int64_t>(f.size()), 1 + keep_alives);
  EXPECT_EQ(f[0], dk1_config_report(1, 0x0c, 0, 300));
  EXPECT_EQ(f[1], keep_alive_report(RiftModel::DK1, 2, 300));
  for (size_t i = 2; i < f.size(); ++i) EXPECT_EQ(f[i], keep_alive_report(RiftModel::DK1, static_cast<uint16_t>(i + 1), 300)) << i;
}

// Without the re-sends (resend interval longer than the device's keep-alive) the same device stops after
// its 300 ms: the test above would see it.
TEST(RiftStream, ADeviceWhoseKeepAliveRunsOutStops) {
  const auto truth = yaw_90(2.0);
  RiftStreamOptions o;
  o.keep_alive_ms = 300;
  o.keep_alive_resend_s = 10;
  Driven t(RiftModel::DK1, truth, o);
  test::RiftEmulator& dk1 = t.device;
  RiftStream& r = t.stream;
  ASSERT_TRUE(t.open());
  ASSERT_NO_FATAL_FAILURE(t.drive(600));
  EXPECT_EQ(dk1.reports_sent(), 301);  // 0..300 ms
  EXPECT_EQ(r.stats().keep_alives, 1);
}

// The magnetometer's yaw correction on the live path (--mag-yaw): the emulated
// DK1 and DK2 read the earth's field in the gyroscope's axes (at their own
// report offsets); with the strongest correction the fused yaw still follows a
// 90 deg/s turn -- a field read in other axes or at the wrong offset turns the
// wrong way as the head turns and pulls the yaw off -- and no reading is taken
// for a disturbance. (One device per test: each test is its own process, and
// a second umockdev testbed in one process trips ThreadSanitizer inside GLib.)
namespace {
void expect_magnetometer_in_gyro_axes(RiftModel model) {
  const auto truth = yaw_90(4.0);
  test::RiftEmulator device(model, truth);
  RiftStreamOptions o;
  o.fusion.yaw_gain = 10;
  RiftStream r(o);
  std::string err;
  ASSERT_TRUE(r.open(err)) << err;
  std::vector<PoseSample> poses;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.stats().samples >= 800; }, poses, "800 samples"));
  expect_fused_motion(r, truth);
  EXPECT_EQ(r.stats().mag_disturbed, 0);
}
}  // namespace

TEST(RiftStream, TheDk1MagnetometerIsReadInTheGyroscopesAxes) { expect_magnetometer_in_gyro_axes(RiftModel::DK1); }
TEST(RiftStream, TheDk2MagnetometerIsReadInTheGyroscopesAxes) { expect_magnetometer_in_gyro_axes(RiftModel::DK2); }

TEST(RiftStream, Dk2MalformedReportUnplugAndReplug) {
  const auto truth = yaw_90(6.0);
  test::RiftEmulator dk2(RiftModel::DK2, truth);
  RiftStreamOptions o;
  o.reconnect_every_s = 0.05;
  RiftStream r(o);
  std::string err;
  ASSERT_TRUE(r.open(err)) << err;
  EXPECT_EQ(r.model(), RiftModel::DK2);
  EXPECT_EQ(dk2.feature_reports().at(0), keep_alive_report(RiftModel::DK2, 1, 10000));
  std::vector<PoseSample> poses;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().samples >= 300; }, poses, "300 samples"));
  dk2.inject_malformed_report();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().malformed == 1 && r.stats().samples >= 500; }, poses,
                                       "the malformed report and 200 samples more"));
  EXPECT_EQ(r.stats().malformed, 1);
  expect_fused_motion(r, truth);  // the report lost is bridged: the next sample is integrated over 2 ms
  // Unplugged: the stream notices, holds the last pose and keeps trying.
  dk2.unplug();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return !r.connected(); }, poses, "the unplug to be noticed"));
  EXPECT_EQ(r.stats().disconnects, 1);
  const PoseSample held = r.last_pose();
  const size_t before = poses.size();
  stream_for(r, 0.2, poses);
  EXPECT_EQ(poses.size(), before);
  EXPECT_EQ(r.last_pose().time_ps, held.time_ps);
  // Plugged back: detached, claimed and streaming again on the same timeline.
  dk2.replug();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.connected() && poses.size() > before + 100; }, poses, "100 poses after the replug"));
  EXPECT_EQ(r.stats().reconnects, 1);
  EXPECT_EQ(r.stats().reconnect_failures, 0);  // an absent device is not a refused one
  for (size_t i = 1; i < poses.size(); ++i) ASSERT_GT(poses[i].time_ps, poses[i - 1].time_ps) << i;
  bool saw_disconnect = false, saw_reconnect = false, saw_malformed = false;
  for (const auto& e : r.take_events()) {
    saw_disconnect |= e.kind == StreamEvent::Kind::Disconnected;
    saw_reconnect |= e.kind == StreamEvent::Kind::Reconnected;
    saw_malformed |= e.kind == StreamEvent::Kind::MalformedReport && e.detail.find("10 bytes") != std::string::npos;
  }
  EXPECT_TRUE(saw_disconnect);
  EXPECT_TRUE(saw_reconnect);
  EXPECT_TRUE(saw_malformed);
}

TEST(RiftStream, NoDeviceGivesAClearAnswer) {
  RiftStream r;
  std::string err;
  EXPECT_FALSE(r.open(err));
  EXPECT_NE(err.find("no Oculus Rift"), std::string::npos) << err;
}

// The quirks of real devices, one after the other on one stream driven by
// the test's clock: 62-byte reports, a count of 7 samples in a report that
// holds 3, 150 malformed reports, and a device restart (its counter back to
// 0). Every count is exact, and every sample is stamped with the millisecond
// its report was sent.
TEST(RiftStream, Dk1QuirksAreTakenCountedAndSummarised) {
  const auto truth = yaw_90(12.0);
  Driven t(RiftModel::DK1, truth);
  test::RiftEmulator& dk1 = t.device;
  RiftStream& r = t.stream;
  ASSERT_TRUE(t.open());
  ASSERT_NO_FATAL_FAILURE(t.drive(199));
  EXPECT_EQ(r.stats().samples, 200);

  dk1.set_report_length(62);
  ASSERT_NO_FATAL_FAILURE(t.drive(200));
  EXPECT_EQ(r.stats().samples, 400);
  EXPECT_EQ(r.stats().malformed, 0);

  dk1.inject_sample_count(7);
  ASSERT_NO_FATAL_FAILURE(t.drive(1));
  EXPECT_EQ(r.stats().samples_lost_on_device, 4);  // 7 taken, 3 held
  EXPECT_EQ(r.stats().samples, 401);               // the two older slots were fused already

  dk1.inject_malformed_report(150);
  ASSERT_NO_FATAL_FAILURE(t.drive(151));
  EXPECT_EQ(r.stats().malformed, 150);
  EXPECT_EQ(r.stats().malformed_short, 150);
  // 150 ms without a sample: a break, bridged by holding the pose. The fused orientation then trails the
  // truth by the turn made in the break (90 deg/s for 150 ms = 13.5 deg), and by nothing else.
  EXPECT_EQ(r.stats().gaps, 1);
  EXPECT_NEAR(r.stats().gap_s, 0.151, 1e-9);
  expect_fused_motion(r, truth, 13.5);

  // The restart sets the counter back by more than the stale tolerance (20 ms): the counter, which wrapped
  // at the 536th report, reads 100 or more after 640 reports.
  ASSERT_NO_FATAL_FAILURE(t.drive(640 - 552));
  EXPECT_EQ(r.stats().clock_reanchors, 0);
  dk1.restart_counter();
  ASSERT_NO_FATAL_FAILURE(t.drive(300));
  EXPECT_EQ(r.stats().clock_reanchors, 1);
  EXPECT_EQ(r.stats().clock_held_reports, 0);  // the arrival it re-anchored at is the device's time
  EXPECT_EQ(r.stats().time_went_back, 0);
  // Since the break the fused motion follows the truth: the trail is still the break's 13.5 deg (the restart
  // itself loses nothing: its first sample is integrated over the device's 1 ms).
  expect_fused_motion(r, truth, 13.5);
  // Each sample at the millisecond its report was sent: no re-anchor moved the timeline.
  ASSERT_NO_FATAL_FAILURE(collect(r, t.poses, static_cast<size_t>(r.stats().samples)));
  for (size_t i = 1; i < t.poses.size(); ++i) {
    ASSERT_GT(t.poses[i].time_ps, t.poses[i - 1].time_ps) << i;
    ASSERT_EQ(t.poses[i].time_ps % kMsPs, 0) << i;
  }
  EXPECT_EQ(t.poses.back().time_ps, t.clock.now_ps());

  // Events: the 1st, 10th and 100th malformed report, one re-anchor; never one line per report.
  int malformed_events = 0, reanchor_events = 0;
  for (const auto& e : r.take_events()) {
    malformed_events += e.kind == StreamEvent::Kind::MalformedReport;
    reanchor_events += e.kind == StreamEvent::Kind::ClockReanchored;
  }
  EXPECT_EQ(malformed_events, 3);
  EXPECT_EQ(reanchor_events, 1);
}

// The device clock end to end on a DK2 driven by the test's clock. The host
// is busy when streaming starts: the first 20 ms of reports arrive together,
// the anchor 20 ms late. The lower envelope sheds that at once: from the 21st
// report on, each sample is stamped with the millisecond it was sent, not
// 20 ms later for the session (the reports of the burst are held 1 ps apart,
// their samples fused). Then the counter glitches 100 ms forward (shed) and
// 2 s forward (a jump: one re-anchor at the arrival); time goes on without a
// step, and neither glitch is integrated as motion.
TEST(RiftStream, Dk2TimesShedALateStartAndSurviveAJump) {
  const auto truth = yaw_90(4.0);
  Driven t(RiftModel::DK2, truth);
  test::RiftEmulator& dk2 = t.device;
  RiftStream& r = t.stream;
  dk2.delay_delivery(20);
  ASSERT_TRUE(t.open());
  ASSERT_NO_FATAL_FAILURE(t.drive(500));
  ASSERT_NO_FATAL_FAILURE(collect(r, t.poses, 501));
  EXPECT_EQ(r.stats().clock_reanchors, 0);
  EXPECT_EQ(r.stats().clock_held_reports, 20);  // the burst's reports after the anchor
  for (size_t k = 1; k < t.poses.size(); ++k) ASSERT_GT(t.poses[k].time_ps, t.poses[k - 1].time_ps) << k;
  for (size_t k = 21; k < t.poses.size(); ++k) ASSERT_EQ(t.poses[k].time_ps, static_cast<int64_t>(k) * kMsPs) << k;
  expect_fused_motion(r, truth);

  // A glitch of 100 ms, inside the lead tolerance: shed by the envelope (no re-anchor, times go on), and
  // its sample integrated over the device's own millisecond, not over the glitch (9 deg at 90 deg/s).
  dk2.jump_counter(100'000);
  ASSERT_NO_FATAL_FAILURE(t.drive(100));
  ASSERT_NO_FATAL_FAILURE(collect(r, t.poses, 601));
  EXPECT_EQ(r.stats().clock_reanchors, 0);
  EXPECT_EQ(r.stats().gaps, 1);
  EXPECT_NEAR(r.stats().gap_s, 0.101, 1e-9);
  for (size_t k = 501; k < t.poses.size(); ++k) ASSERT_EQ(t.poses[k].time_ps, static_cast<int64_t>(k) * kMsPs) << k;
  expect_fused_motion(r, truth);

  dk2.jump_counter(2'000'000);  // 2 s of microseconds
  ASSERT_NO_FATAL_FAILURE(t.drive(100));
  ASSERT_NO_FATAL_FAILURE(collect(r, t.poses, 701));
  EXPECT_EQ(r.stats().clock_reanchors, 1);
  for (size_t k = 601; k < t.poses.size(); ++k) ASSERT_EQ(t.poses[k].time_ps, static_cast<int64_t>(k) * kMsPs) << k;
  EXPECT_EQ(r.stats().gaps, 1);  // the jump was in the counter, not in the samples
  expect_fused_motion(r, truth);
}

// Transfer errors, driven by the test's clock: a few (the host controller
// timing out, a bus error) are retried with nothing lost; 20 in a row are
// taken for an unplug: the stream lets go, reconnects, and streams on.
TEST(RiftStream, TransferErrorsAreRetriedAndARunOfThemIsAnUnplug) {
  RiftStreamOptions o;
  o.reconnect_every_s = 1e-9;  // at once: the test's clock stands still while it waits
  Driven t(RiftModel::DK1, yaw_90(4.0), o);
  RiftStream& r = t.stream;
  ASSERT_TRUE(t.open());
  ASSERT_NO_FATAL_FAILURE(t.drive(100));
  t.device.fail_transfers(5, ETIME);
  ASSERT_NO_FATAL_FAILURE(t.drive(100));
  EXPECT_EQ(r.stats().transfer_errors, 5);
  EXPECT_EQ(r.stats().disconnects, 0);
  EXPECT_EQ(r.stats().samples, 201);  // every report: the errors cost no sample
  EXPECT_EQ(r.stats().gaps, 0);
  t.device.fail_transfers(20, EPROTO);
  ASSERT_NO_FATAL_FAILURE(t.drive(100));
  EXPECT_EQ(r.stats().transfer_errors, 25);  // every one counted; the 20th in a row is the unplug
  EXPECT_EQ(r.stats().disconnects, 1);
  EXPECT_EQ(r.stats().reconnects, 1);
  EXPECT_TRUE(r.connected());
  EXPECT_EQ(r.stats().samples, 301);
  bool said = false;
  for (const auto& e : r.take_events())
    said |= e.kind == StreamEvent::Kind::Disconnected && e.detail.find("20 transfers in a row failed") != std::string::npos;
  EXPECT_TRUE(said);
}

// A hung host controller: the device is unplugged while libusb never gives
// the transfers in flight back (not on the cancel, not on the unplug). The
// stream abandons them after 1 s -- kept, not freed: libusb may still write
// into them -- says so, reconnects when the device is back, and frees each
// when it finally does come back, then closes the old handle. The suite runs
// under ASan and LeakSanitizer too: nothing is freed twice, used after it
// was freed, or left behind.
TEST(RiftStream, TransfersLibusbNeverGivesBackAreFreedWhenTheyComeBack) {
  const auto truth = yaw_90(30.0);
  test::RiftEmulator dk2(RiftModel::DK2, truth);
  RiftStreamOptions o;
  o.keep_alive_resend_s = 0.05;  // the unplug is found by the next keep-alive (no transfer comes back to say so)
  o.reconnect_every_s = 0.05;
  RiftStream r(o);
  std::string err;
  ASSERT_TRUE(r.open(err)) << err;
  std::vector<PoseSample> poses;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().samples >= 100; }, poses, "100 samples"));
  dk2.withhold_transfers();
  dk2.unplug();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().transfers_abandoned > 0; }, poses, "the transfers abandoned"));
  // Those in flight at the unplug: all four, or three when one was between its completion and its
  // resubmission (that one fails to resubmit and is freed at once).
  const int64_t abandoned = r.stats().transfers_abandoned;
  EXPECT_GE(abandoned, o.transfers_in_flight - 1);
  EXPECT_LE(abandoned, o.transfers_in_flight);
  EXPECT_EQ(r.stats().transfers_abandoned_back, 0);
  EXPECT_EQ(r.stats().disconnects, 1);
  bool said = false;
  for (const auto& e : r.take_events())
    said |= e.kind == StreamEvent::Kind::Disconnected && e.detail.find("not back from libusb after 1 s") != std::string::npos;
  EXPECT_TRUE(said);

  dk2.replug();
  const int64_t before = r.stats().samples;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.stats().reconnects >= 1 && r.stats().samples >= before + 100; }, poses,
                                       "streaming again beside the abandoned transfers"));
  dk2.give_back();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.stats().transfers_abandoned_back == abandoned; }, poses,
                                       "the abandoned transfers back"));
  const int64_t after = r.stats().samples;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.stats().samples >= after + 100; }, poses, "streaming on"));
  EXPECT_EQ(r.stats().disconnects, 1);
  EXPECT_TRUE(r.connected());
}

// A consumer slower than the device: the stream keeps max_pending_s of
// samples (0.2 s at 1 kHz: 200), drops the oldest beyond, counts them and
// says so once per power of ten. Driven by the test's clock: the consumer
// takes nothing for 700 ms of it, then gets exactly the newest 200.
TEST(RiftStream, AConsumerSlowerThanTheDeviceGetsTheNewestWithinTheBound) {
  const auto truth = yaw_90(4.0);
  RiftStreamOptions o;
  o.max_pending_s = 0.2;
  Driven t(RiftModel::DK2, truth, o);
  RiftStream& r = t.stream;
  ASSERT_TRUE(t.open());
  ASSERT_NO_FATAL_FAILURE(t.drive(699, nullptr));  // stats() does not consume
  std::vector<PoseSample> got;
  r.poll(0, got);
  const StreamStats st = r.stats();
  ASSERT_EQ(st.samples, 700);
  ASSERT_EQ(got.size(), 200u);
  for (size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i].time_ps, static_cast<int64_t>(500 + i) * kMsPs) << i;
  EXPECT_EQ(st.dropped_unconsumed, 500);
  int behind = 0;
  for (const auto& e : r.take_events()) behind += e.kind == StreamEvent::Kind::ConsumerBehind;
  EXPECT_EQ(behind, 3);  // the 1st, 10th, 100th drop
  RiftStreamOptions none;
  none.max_pending_s = 0;
  EXPECT_THROW(RiftStream{none}, std::invalid_argument);
}

// The endpoint halts mid-stream: the halt is cleared once, the transfers
// resubmitted, and streaming goes on without a disconnect.
TEST(RiftStream, AStalledEndpointIsClearedAndStreamingGoesOn) {
  const auto truth = yaw_90(4.0);
  test::RiftEmulator dk2(RiftModel::DK2, truth);
  RiftStream r;
  std::string err;
  ASSERT_TRUE(r.open(err)) << err;
  std::vector<PoseSample> poses;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().samples >= 200; }, poses, "200 samples"));
  dk2.stall();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().stalls >= 1; }, poses, "the stall"));
  const int64_t after_stall = r.stats().samples;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&] { return r.stats().samples >= after_stall + 200; }, poses, "200 samples after the stall"));
  EXPECT_GE(dk2.clear_halts(), 1);
  EXPECT_EQ(r.stats().disconnects, 0);
  EXPECT_TRUE(r.connected());
  bool said = false;
  for (const auto& e : r.take_events()) said |= e.kind == StreamEvent::Kind::Stalled && e.detail.find("halt cleared") != std::string::npos;
  EXPECT_TRUE(said);
}

// Interface 0 claimed by another program: a clear answer, not the udev hint.
TEST(RiftStream, AnInterfaceInUseElsewhereIsSaidSo) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(1.0));
  dk1.hold_interface_elsewhere();
  RiftStream r;
  std::string err;
  EXPECT_FALSE(r.open(err));
  EXPECT_NE(err.find("in use by another program"), std::string::npos) << err;
  EXPECT_EQ(err.find("udev"), std::string::npos) << err;
}

// A device with the Rift's ids but not its layout is refused with what was found.
TEST(RiftStream, ADeviceWithoutTheInterruptEndpointIsRefused) {
  test::RiftEmulator odd(RiftModel::DK1, yaw_90(1.0), test::RiftEmulator::Layout::NoInterruptIn);
  RiftStream r;
  std::string err;
  EXPECT_FALSE(r.open(err));
  EXPECT_NE(err.find("no interrupt IN endpoint 0x81"), std::string::npos) << err;
  EXPECT_NE(err.find("found: 0x02 bulk"), std::string::npos) << err;
  EXPECT_FALSE(odd.interface_claimed());
}

// Two trackers attached: told apart by bus, address and serial number; none
// taken silently; each chosen by its serial number or its BUS:ADDR.
TEST(RiftStream, TwoTrackersAreToldApartAndChosenBySerialOrAddress) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(20.0), test::RiftEmulator::Layout::Rift, {2, "DK1-A"});
  test::RiftEmulator dk2(RiftModel::DK2, yaw_90(20.0), test::RiftEmulator::Layout::Rift, {3, "DK2-B"});
  const UsbScan scan = scan_usb_trackers();
  ASSERT_TRUE(scan.usb_available) << scan.usb_error;
  ASSERT_EQ(scan.trackers.size(), 2u);
  EXPECT_EQ(describe(scan.trackers[0]) + "; " + describe(scan.trackers[1]),
            "DK1 bus 001 address 002 serial DK1-A; DK2 bus 001 address 003 serial DK2-B");
  EXPECT_TRUE(scan.trackers[0].can_open && scan.trackers[1].can_open);

  std::string err;
  {
    RiftStream none;
    EXPECT_FALSE(none.open(err));
    EXPECT_NE(err.find("2 trackers attached (DK1 bus 001 address 002 serial DK1-A; DK2 bus 001 address 003 serial DK2-B): "
                       "choose one with --device"),
              std::string::npos)
        << err;
    EXPECT_FALSE(dk1.interface_claimed() || dk2.interface_claimed());
  }
  const struct {
    std::string device;
    RiftModel model;
  } picks[] = {{"DK2-B", RiftModel::DK2}, {"1:2", RiftModel::DK1}, {"001:003", RiftModel::DK2}};
  for (const auto& p : picks) {
    RiftStreamOptions o;
    o.device = p.device;
    RiftStream r(o);
    ASSERT_TRUE(r.open(err)) << p.device << ": " << err;
    EXPECT_EQ(r.model(), p.model) << p.device;
    EXPECT_EQ((p.model == RiftModel::DK1 ? dk1 : dk2).interface_claimed(), true) << p.device;
    EXPECT_FALSE((p.model == RiftModel::DK1 ? dk2 : dk1).interface_claimed()) << p.device;
    std::vector<PoseSample> got;
    stream_until(r, [&] { return got.size() >= 20; }, got, "samples");
  }
  for (const char* bad : {"DK3", "1:9", "2:2", "1:", ":2", "x:y"}) {
    RiftStreamOptions o;
    o.device = bad;
    RiftStream r(o);
    EXPECT_FALSE(r.open(err)) << bad;
    EXPECT_NE(err.find("no tracker is '" + std::string(bad) + "' (attached: DK1 bus 001 address 002 serial DK1-A; DK2"),
              std::string::npos)
        << err;
  }
}

// A tracker another program streams is listed as such, not as ready.
TEST(RiftStream, TheListSaysWhichTrackerIsInUse) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(1.0), test::RiftEmulator::Layout::Rift, {2, "FREE"});
  test::RiftEmulator dk2(RiftModel::DK2, yaw_90(1.0), test::RiftEmulator::Layout::Rift, {5, "TAKEN"});
  dk2.hold_interface_elsewhere();
  const UsbScan scan = scan_usb_trackers();
  ASSERT_EQ(scan.trackers.size(), 2u);
  EXPECT_TRUE(scan.trackers[0].can_open) << scan.trackers[0].problem;
  EXPECT_EQ(scan.trackers[0].serial, "FREE");
  EXPECT_FALSE(scan.trackers[1].can_open);
  EXPECT_EQ(scan.trackers[1].serial, "TAKEN");
  EXPECT_EQ(scan.trackers[1].address, 5);
  EXPECT_NE(scan.trackers[1].problem.find("in use by another program"), std::string::npos) << scan.trackers[1].problem;
  EXPECT_FALSE(dk1.interface_claimed());  // listing claimed and released it
}

// After the first connection the stream reconnects only to the tracker it
// streamed: another one plugged in while it is away does not take its place.
TEST(RiftStream, AReconnectionTakesOnlyTheSameTracker) {
  test::RiftEmulator dk1(RiftModel::DK1, yaw_90(30.0), test::RiftEmulator::Layout::Rift, {2, "FIRST"});
  test::RiftEmulator dk2(RiftModel::DK2, yaw_90(30.0), test::RiftEmulator::Layout::Rift, {3, "OTHER"});
  dk2.unplug();  // not there yet
  RiftStreamOptions o;
  o.reconnect_every_s = 0.02;
  RiftStream r(o);
  std::string err;
  ASSERT_TRUE(r.open(err)) << err;  // the only tracker attached
  EXPECT_EQ(r.model(), RiftModel::DK1);
  std::vector<PoseSample> poses;
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().samples >= 50; }, poses, "50 samples"));
  dk1.unplug();
  dk2.replug();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.stats().reconnect_failures >= 3; }, poses, "three refused reconnections"));
  EXPECT_FALSE(r.connected());
  EXPECT_FALSE(dk2.interface_claimed());
  bool named = false;
  for (const auto& e : r.take_events())
    named |= e.kind == StreamEvent::Kind::OpenFailed &&
             e.detail.find("waiting for the tracker streamed before (serial FIRST): attached: DK2 bus 001 address 003 serial OTHER") !=
                 std::string::npos;
  EXPECT_TRUE(named);
  dk1.replug();
  ASSERT_NO_FATAL_FAILURE(stream_until(r, [&r] { return r.connected(); }, poses, "the same tracker back"));
  EXPECT_EQ(r.model(), RiftModel::DK1);
  EXPECT_TRUE(dk1.interface_claimed());
  EXPECT_FALSE(dk2.interface_claimed());
}
