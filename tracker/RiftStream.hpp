// Streaming from an Oculus Rift DK1/DK2 IMU through libusb-1.0: find the
// device (vendor 0x2833), detach the kernel's HID driver, claim interface 0,
// send the config and keep-alive feature reports (and re-send the keep-alive
// every few seconds, well inside its interval), keep interrupt transfers in
// flight on endpoint 0x81, decode every report (untrusted: malformed ones are
// counted and skipped), map the device's wrapping timestamps to one timeline
// (DeviceClock) and fuse gyro and accelerometer into orientations (Fusion).
//
// Robustness: when the device goes away mid-run the last good pose is held,
// the event is reported, and the device is looked for again every
// `reconnect_every_s`; when it is back, streaming resumes on the same
// timeline. Permission problems say where the udev rules are.
//
// By default a background thread services the device continuously (as the
// kernel would queue reports), so a consumer that is busy rendering loses
// nothing within max_pending_s (beyond it the oldest are dropped, counted);
// poll() then only collects what was fused. With
// `background_thread = false` everything happens inside poll() instead.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Fusion.hpp"
#include "OculusReport.hpp"
#include "PoseSample.hpp"

namespace arp::tracker {

struct RiftStreamOptions {
  std::string device;                // which tracker: its serial number or BUS:ADDR; empty: the only one attached
  uint16_t keep_alive_ms = 10000;    // the interval the device is told
  double keep_alive_resend_s = 3.0;  // how often it is re-sent
  int transfers_in_flight = 4;
  double reconnect_every_s = 0.5;
  bool background_thread = true;
  // Fused samples kept for the consumer, s of device time (> 0): 10 s at 1 kHz is 10 000 samples, about
  // 1 MB. A consumer that falls further behind loses the oldest, counted (dropped_unconsumed) and reported.
  double max_pending_s = 10.0;
  FusionParams fusion;
  // The host's clock, ps from any origin, non-decreasing, thread-safe (the pump and the consumer read it): when reports
  // arrive (DeviceClock's arrivals), when keep-alives are due, when to try reconnecting, event times.
  // Empty: the steady clock. Tests drive it, with the emulated device, so that nothing they check
  // depends on how fast the machine runs. (Waits for USB events stay on the wall clock.)
  std::function<int64_t()> host_clock;
};

// Events that repeat (a malformed report, a stale timestamp, a clock
// re-anchor) are reported the 1st, 10th, 100th, ... time, each saying which
// occurrence it is; the stats count every one.
struct StreamEvent {
  enum class Kind { Opened, Disconnected, Reconnected, MalformedReport, TimeWentBack, ClockReanchored, ConsumerBehind, Stalled, OpenFailed };
  Kind kind;
  double at_s;         // seconds since the stream was created (wall clock)
  std::string detail;
};
const char* to_string(StreamEvent::Kind k);

struct StreamStats {
  int64_t reports = 0, samples = 0, keep_alives = 0, disconnects = 0, reconnects = 0;
  int64_t malformed = 0;                                          // refused reports, all kinds
  int64_t malformed_empty = 0, malformed_wrong_id = 0, malformed_short = 0;  // ... by kind
  int64_t samples_lost_on_device = 0;  // counted by the device beyond what its reports held
  int64_t time_went_back = 0;          // stale reports skipped (DeviceClock: backwards)
  int64_t clock_reanchors = 0;         // device restarts and timestamp jumps (DeviceClock: reanchored)
  int64_t clock_held_reports = 0;      // reports skipped while the clock caught up after a re-anchor (DeviceClock: held)
  int64_t gaps = 0;                    // breaks in the samples (a reconnection, a lost run of reports) bridged by holding the pose
  int64_t dropped_unconsumed = 0;      // samples dropped because the consumer fell max_pending_s behind
  int64_t stalls = 0;                  // endpoint halts cleared
  int64_t transfer_errors = 0;         // transfers that failed transiently and were resubmitted
  int64_t reconnect_failures = 0;      // a device found but refused while reconnecting
  int64_t transfers_abandoned = 0;     // transfers libusb did not give back within 1 s of a cancel (kept, not freed)
  int64_t transfers_abandoned_back = 0;  // ... that came back later and were freed then
  int64_t mag_disturbed = 0;           // magnetometer readings not used for yaw (fusion.yaw_gain > 0): the field's strength was off
  double gap_s = 0;                    // their total length, s
  bool kernel_driver_detached = false;
};

// Every counter of StreamStats, named, in report order: the run's report and
// `tracker record`'s summary iterate this list.
template <class F>
void for_each_counter(const StreamStats& s, F&& f) {
  f("reports", s.reports);
  f("samples", s.samples);
  f("malformed", s.malformed);
  f("malformed_empty", s.malformed_empty);
  f("malformed_wrong_id", s.malformed_wrong_id);
  f("malformed_short", s.malformed_short);
  f("samples_lost_on_device", s.samples_lost_on_device);
  f("time_went_back", s.time_went_back);
  f("clock_reanchors", s.clock_reanchors);
  f("clock_held_reports", s.clock_held_reports);
  f("gaps", s.gaps);
  f("dropped_unconsumed", s.dropped_unconsumed);
  f("stalls", s.stalls);
  f("transfer_errors", s.transfer_errors);
  f("reconnect_failures", s.reconnect_failures);
  f("transfers_abandoned", s.transfers_abandoned);
  f("transfers_abandoned_back", s.transfers_abandoned_back);
  f("mag_disturbed", s.mag_disturbed);
  f("disconnects", s.disconnects);
  f("reconnects", s.reconnects);
  f("keep_alives", s.keep_alives);
}
// The device's quirks: "name value, ..." for every counter that is not zero
// beyond the usual ones (reports, samples, malformed, disconnects,
// reconnects, keep-alives); empty when there were none.
std::string unusual_counters(const StreamStats& s);

// Where the udev rules file ships and what it says (docs/tracker.md).
extern const char* const kUdevRulesHint;

class RiftStream {
 public:
  explicit RiftStream(const RiftStreamOptions& o = {});
  ~RiftStream();
  RiftStream(const RiftStream&) = delete;
  RiftStream& operator=(const RiftStream&) = delete;

  // Opens the first DK1/DK2. false, with the reason in `error`, when there is
  // none, USB is unavailable, or it cannot be opened (permission: see kUdevRulesHint).
  bool open(std::string& error);
  // Whether the last failed open was a choice the trackers attached cannot satisfy: --device names none of
  // them, or several are attached and none was named (a usage error; no tracker at all is not one).
  bool choice_refused() const;
  // Handles USB events for up to timeout_ms (and keep-alives, reconnection);
  // appends the poses fused since the last call to `out`.
  void poll(int timeout_ms, std::vector<PoseSample>& out);

  bool connected() const;
  RiftModel model() const;
  StreamStats stats() const;
  // The stats and the last pose taken together (under one lock: the pump fuses between two calls).
  struct Snapshot {
    StreamStats stats;
    PoseSample last;
  };
  Snapshot snapshot() const;
  std::vector<StreamEvent> take_events();
  // The last fused pose (held while disconnected); time 0 and identity before the first.
  PoseSample last_pose() const;
  // Now on the poses' timeline (picoseconds since the stream was created), to place them on another.
  int64_t now_ps() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> p_;
};

}  // namespace arp::tracker
