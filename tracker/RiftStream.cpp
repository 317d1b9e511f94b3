#include "RiftStream.hpp"

#include <libusb-1.0/libusb.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_set>

#include "DeviceClock.hpp"
#include "RiftProtocol.hpp"
#include "UsbTrackers.hpp"

namespace arp::tracker {

const char* const kUdevRulesHint =
    "install the udev rules shipped in scripts/udev/70-arpsim-oculus.rules "
    "(sudo cp scripts/udev/70-arpsim-oculus.rules /etc/udev/rules.d/ && sudo udevadm control --reload-rules && "
    "replug the tracker; docs/tracker.md)";

std::string unusual_counters(const StreamStats& s) {
  std::string out;
  for_each_counter(s, [&out](const std::string& name, int64_t v) {
    static const char* const kUsual[] = {"reports", "samples", "malformed", "disconnects", "reconnects", "keep_alives"};
    if (v == 0 || std::find(std::begin(kUsual), std::end(kUsual), name) != std::end(kUsual)) return;
    out += (out.empty() ? "" : ", ") + name + " " + std::to_string(v);
  });
  return out;
}

const char* to_string(StreamEvent::Kind k) {
  switch (k) {
    case StreamEvent::Kind::Opened: return "opened";
    case StreamEvent::Kind::Disconnected: return "disconnected";
    case StreamEvent::Kind::Reconnected: return "reconnected";
    case StreamEvent::Kind::MalformedReport: return "malformed report";
    case StreamEvent::Kind::TimeWentBack: return "device time went back";
    case StreamEvent::Kind::ClockReanchored: return "device clock re-anchored";
    case StreamEvent::Kind::ConsumerBehind: return "consumer behind";
    case StreamEvent::Kind::Stalled: return "endpoint stalled";
    case StreamEvent::Kind::OpenFailed: return "open failed";
  }
  return "?";
}

struct RiftStream::Impl {
  RiftStreamOptions opt;
  libusb_context* ctx = nullptr;
  libusb_device_handle* handle = nullptr;
  // Written by connect() on the pump thread (a replug may bring the other model), read by model().
  std::atomic<RiftModel> model{RiftModel::DK1};
  std::atomic<bool> is_connected{false};
  bool ever_opened = false;
  std::atomic<bool> choice_refused{false};  // the last connect() failed choosing among the trackers attached (pump writes)
  bool streamed_before = false;  // reconnections take only the tracker streamed before (connect() only)
  UsbTrackerInfo streamed;       // as found at its last connection
  // Shared with the consumer (the pump thread writes, poll() reads): guarded by mu.
  mutable std::mutex mu;
  std::condition_variable arrived;
  std::thread pump;
  std::atomic<bool> stop{false};
  // Transfers of this connection (all owned: freed by release()), those libusb holds now, and those
  // back with STALL waiting for clear_stall(). Touched only on the pump thread.
  std::vector<libusb_transfer*> transfers;
  std::unordered_set<libusb_transfer*> flying;
  std::vector<libusb_transfer*> stalled;
  // Transfers of an earlier connection libusb never gave back (see release()): freed when they come
  // back, their handles closed when none is left.
  std::unordered_set<libusb_transfer*> abandoned;
  std::vector<libusb_device_handle*> abandoned_handles;
  int transfer_errors_in_a_row = 0;
  uint16_t command_id = 1;
  // When the stream was made: on the host clock asked for, or on the steady clock (whose origin, the
  // machine's boot, may be more than int64_t picoseconds ago).
  int64_t t0_ps = 0;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double last_keep_alive_s = -1e9, last_attempt_s = -1e9;
  std::unique_ptr<DeviceClock> clock;
  Fusion fusion;
  bool fusion_started = false;
  int64_t last_sample_ps = 0;
  // The last fused sample on the device's own time, and which stretch of it (a new one at each re-anchor
  // and each connection: device times compare only within one).
  int64_t last_device_ps = 0;
  int64_t segment = 0, last_segment = -1;
  StreamStats stats;
  std::vector<StreamEvent> events;
  std::deque<PoseSample> pending;  // bounded: max_pending_s of device time
  PoseSample last;

  explicit Impl(const RiftStreamOptions& o) : opt(o), fusion(o.fusion) {
    if (opt.host_clock) t0_ps = opt.host_clock();
  }
  void step(int timeout_ms);

  int64_t now_ps() const {
    if (opt.host_clock) return opt.host_clock() - t0_ps;
    const int64_t ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
    return ns < INT64_MAX / 1000 ? ns * 1000 : INT64_MAX;  // (saturated after 106 days of streaming)
  }
  double now_s() const { return static_cast<double>(now_ps()) * 1e-12; }
  void event(StreamEvent::Kind k, std::string detail) {
    std::lock_guard<std::mutex> lock(mu);
    events.push_back({k, now_s(), std::move(detail)});
  }
  // A repeating event: reported the 1st, 10th, 100th ... time (nth: the count
  // including this one), so a device sending 1000 bad reports a second does
  // not flood the terminal. Called with mu held.
  void repeating_event_locked(StreamEvent::Kind k, int64_t nth, const std::string& detail) {
    int64_t p = 1;
    while (p < nth && p <= INT64_MAX / 10) p *= 10;
    if (p != nth) return;
    events.push_back({k, now_s(), nth == 1 ? detail : detail + " (the " + std::to_string(nth) + "th; every one is counted)"});
  }

  int send_feature(const std::vector<uint8_t>& report) {
    const int rc = libusb_control_transfer(handle, kHidRequestTypeOut, kHidSetReport, static_cast<uint16_t>(kHidFeatureReport | report[0]), 0,
                                           const_cast<unsigned char*>(report.data()), static_cast<uint16_t>(report.size()), 1000);
    ++command_id;
    return rc;
  }

  bool send_keep_alive() {
    const int rc = send_feature(keep_alive_report(model, command_id, opt.keep_alive_ms));
    if (rc < 0) return false;
    std::lock_guard<std::mutex> lock(mu);
    ++stats.keep_alives;
    last_keep_alive_s = now_s();
    return true;
  }

  static void LIBUSB_CALL on_transfer(libusb_transfer* t) { static_cast<Impl*>(t->user_data)->completed(t); }

  // A transfer came back. Its status decides: completed -> decode and resubmit; stalled -> wait for the
  // halt to be cleared (step() does it: no synchronous libusb call inside a callback); a transient error
  // (timeout, overflow, error) -> resubmit, up to kMaxTransferErrors in a row; no device -> unplugged.
  static constexpr int kMaxTransferErrors = 20;
  void completed(libusb_transfer* t) {
    if (abandoned.erase(t)) {  // an earlier connection's, back at last: nothing more to do with it
      libusb_free_transfer(t);
      std::lock_guard<std::mutex> lock(mu);
      ++stats.transfers_abandoned_back;
      return;
    }
    flying.erase(t);
    switch (t->status) {
      case LIBUSB_TRANSFER_COMPLETED:
        transfer_errors_in_a_row = 0;
        report(t->buffer, static_cast<size_t>(t->actual_length));
        resubmit(t);
        return;
      case LIBUSB_TRANSFER_CANCELLED:
        return;
      case LIBUSB_TRANSFER_NO_DEVICE:
        lost("the device is gone");
        return;
      case LIBUSB_TRANSFER_STALL:
        if (is_connected) stalled.push_back(t);  // (after a loss release() frees it with the rest)
        return;
      default: {
        {
          std::lock_guard<std::mutex> lock(mu);
          ++stats.transfer_errors;
        }
        if (++transfer_errors_in_a_row >= kMaxTransferErrors) {
          lost(std::to_string(kMaxTransferErrors) + " transfers in a row failed (" + libusb_error_name(t->status) + ")");
          return;
        }
        resubmit(t);
      }
    }
  }

  void resubmit(libusb_transfer* t) {
    if (!is_connected) return;
    const int rc = libusb_submit_transfer(t);
    if (rc == 0) flying.insert(t);
    else lost(std::string("resubmitting a transfer failed: ") + libusb_strerror(rc));
  }

  // Endpoint 0x81 halted: clear the halt once, then resubmit every stalled transfer.
  void clear_stall() {
    if (stalled.empty() || !is_connected) return;
    const int rc = libusb_clear_halt(handle, 0x81);
    {
      std::lock_guard<std::mutex> lock(mu);
      ++stats.stalls;
      repeating_event_locked(StreamEvent::Kind::Stalled, stats.stalls,
                             rc == 0 ? "endpoint 0x81 stalled; halt cleared, streaming on"
                                     : std::string("endpoint 0x81 stalled; clearing the halt failed: ") + libusb_strerror(rc));
    }
    if (rc != 0) {
      stalled.clear();
      lost("the endpoint stalled and its halt could not be cleared");
      return;
    }
    std::vector<libusb_transfer*> again;
    again.swap(stalled);
    for (auto* t : again) resubmit(t);
  }

  void lost(const std::string& why) {
    if (!is_connected.exchange(false)) return;
    // Repeating: a device that connects and fails again cycles every reconnect_every_s.
    std::lock_guard<std::mutex> lock(mu);
    ++stats.disconnects;
    repeating_event_locked(StreamEvent::Kind::Disconnected, stats.disconnects, why + "; holding the last pose, retrying");
  }

  void report(const uint8_t* data, size_t n) {
    ImuReport r;
    std::string err;
    ReportFault fault = ReportFault::None;
    std::unique_lock<std::mutex> lock(mu);
    if (!decode_report(model, data, n, r, err, &fault)) {
      ++stats.malformed;
      ++(fault == ReportFault::Empty ? stats.malformed_empty : fault == ReportFault::WrongId ? stats.malformed_wrong_id : stats.malformed_short);
      repeating_event_locked(StreamEvent::Kind::MalformedReport, stats.malformed, err);
      return;
    }
    ++stats.reports;
    stats.samples_lost_on_device += r.reported_sample_count - r.sample_count;
    const int64_t arrival = now_ps();
    const DeviceClock::Mapped m = clock->map(r.timestamp, arrival);
    if (m.backwards) {
      ++stats.time_went_back;
      repeating_event_locked(StreamEvent::Kind::TimeWentBack, stats.time_went_back,
                             "report timestamp " + std::to_string(r.timestamp) + " is not after the last; its samples skipped");
      return;
    }
    if (m.reanchored) {
      ++stats.clock_reanchors;
      if (m.held) ++stats.clock_held_reports;
      char what[120];
      std::snprintf(what, sizeof what, "the device's timestamp jumped %+.1f ms (a restart or a glitch); time carries on from the host clock",
                    static_cast<double>(m.jump_ps) * 1e-9);
      repeating_event_locked(StreamEvent::Kind::ClockReanchored, stats.clock_reanchors, what);
    }
    if (m.held && !m.reanchored) ++stats.clock_held_reports;
    constexpr int64_t kSamplePs = 1'000'000'000;  // 1000 Hz
    // Longer than this between two samples is a break (a reconnection, a re-anchor): nothing is known
    // of the head in between, so the pose is held across it rather than the gyro integrated over it.
    constexpr int64_t kGapPs = 20 * kSamplePs;
    if (m.reanchored) ++segment;
    for (int i = 0; i < r.sample_count; ++i) {
      const auto& s = r.samples[static_cast<size_t>(i)];
      const int64_t back = static_cast<int64_t>(r.sample_count - 1 - i) * kSamplePs;
      const int64_t device_ps = m.device_ps - back;
      const bool same_stretch = fusion_started && segment == last_segment;
      // Already fused (a count overlapping the last report's): judged on the device's time within a
      // stretch (the timeline may have moved earlier under it, DeviceClock's envelope), else on the timeline.
      if (same_stretch ? device_ps <= last_device_ps : fusion_started && !m.held && m.time_ps - back <= last_sample_ps) continue;
      // Held (the clock catching up), or the envelope moving the timeline earlier by more than the
      // samples' spacing: 1 ps after the last sample, so the timeline never goes back.
      const int64_t t = m.held ? last_sample_ps + 1 : fusion_started ? std::max(m.time_ps - back, last_sample_ps + 1) : m.time_ps - back;
      const glm::dvec3 gyro(gyro_rad_s(s.gyro[0]), gyro_rad_s(s.gyro[1]), gyro_rad_s(s.gyro[2]));
      const glm::dvec3 accel(accel_m_s2(s.accel[0]), accel_m_s2(s.accel[1]), accel_m_s2(s.accel[2]));
      // Integrated over the device's own step between the samples: the timeline's step also holds the
      // host's corrections (the envelope, holding). Across a re-anchor or a reconnection only the sample's
      // own period is known.
      // A break is judged on the device's step within a stretch (the envelope may have shed a counter
      // glitch from the timeline: the step is then the glitch, not motion), else on the timeline's.
      int64_t dt_ps = same_stretch ? device_ps - last_device_ps : kSamplePs;
      const int64_t step = same_stretch ? dt_ps : t - last_sample_ps;
      if (fusion_started && (same_stretch || !m.held) && step > kGapPs) {
        ++stats.gaps;
        stats.gap_s += static_cast<double>(step) * 1e-12;
        dt_ps = kSamplePs;  // this sample's own period only
      }
      if (opt.fusion.yaw_gain > 0) {
        // The report's one magnetometer reading (1e-4 gauss, the gyroscope's axes) for each of its samples.
        const glm::dvec3 mag(r.magnetometer[0] * 1e-4, r.magnetometer[1] * 1e-4, r.magnetometer[2] * 1e-4);
        fusion.update(gyro, accel, mag, static_cast<double>(dt_ps) * 1e-12);
        stats.mag_disturbed = fusion.mag_refused();
      } else {
        fusion.update(gyro, accel, static_cast<double>(dt_ps) * 1e-12);
      }
      fusion_started = true;
      last_sample_ps = t;
      last_device_ps = device_ps;
      last_segment = segment;
      ++stats.samples;
      PoseSample p;
      p.time_ps = t;
      p.orientation = fusion.orientation();
      p.has_angular_velocity = true;
      p.angular_velocity = gyro;
      pending.push_back(p);
      while (static_cast<double>(pending.back().time_ps - pending.front().time_ps) >= opt.max_pending_s * 1e12) {
        pending.pop_front();
        ++stats.dropped_unconsumed;
        char what[120];
        std::snprintf(what, sizeof what, "the consumer is more than %g s of samples behind; the oldest are dropped", opt.max_pending_s);
        repeating_event_locked(StreamEvent::Kind::ConsumerBehind, stats.dropped_unconsumed, what);
      }
      last = p;
    }
    lock.unlock();
    arrived.notify_all();
  }

  // Finds, opens, claims, configures and starts streaming. false + error otherwise.
  bool connect(std::string& error) {
    libusb_device** list = nullptr;
    const ssize_t n = libusb_get_device_list(ctx, &list);
    if (n < 0) {
      error = std::string("libusb could not list devices: ") + libusb_strerror(static_cast<int>(n));
      return false;
    }
    // The tracker asked for (--device), or the only one; after the first connection, the same one again
    // (choose_again: by its serial number -- a replug moves its address; another tracker must not take its place).
    const std::vector<FoundTracker> all = find_trackers(list, static_cast<long>(n), false);
    std::vector<UsbTrackerInfo> infos;
    for (const auto& f : all) infos.push_back(f.info);
    const int k = streamed_before ? choose_again(infos, streamed, error) : choose_tracker(infos, opt.device, error);
    choice_refused = k < 0 && !infos.empty();
    if (k < 0) {
      libusb_free_device_list(list, 1);
      // None at all keeps choose_tracker's "no Oculus Rift ..." (an absent device is not a refusal: step() stays quiet).
      if (streamed_before && infos.empty()) error = "no Oculus Rift attached";
      return false;
    }
    libusb_device* dev = all[static_cast<size_t>(k)].device;
    const RiftModel found = all[static_cast<size_t>(k)].info.model;
    const UsbTrackerInfo chosen = all[static_cast<size_t>(k)].info;
    char where[64];
    std::snprintf(where, sizeof where, "/dev/bus/usb/%03d/%03d", libusb_get_bus_number(dev), libusb_get_device_address(dev));
    int rc = libusb_open(dev, &handle);
    libusb_free_device_list(list, 1);
    if (rc != 0) {
      handle = nullptr;
      error = std::string("cannot open ") + where + ": " + libusb_strerror(rc) +
              (rc == LIBUSB_ERROR_ACCESS ? std::string("; ") + kUdevRulesHint : std::string());
      return false;
    }
    model = found;
    bool detached_here = false;
    auto fail = [&](const std::string& what, int code) {
      error = what + " on " + where + ": " + libusb_strerror(code) +
              (code == LIBUSB_ERROR_ACCESS ? std::string("; ") + kUdevRulesHint
               : code == LIBUSB_ERROR_BUSY ? std::string("; interface 0 is in use by another program (another driver or tracker tool): close it")
                                           : std::string());
      if (detached_here) libusb_attach_kernel_driver(handle, 0);  // leave the device as it was found
      libusb_close(handle);
      handle = nullptr;
      return false;
    };
    // The layout streaming needs: interface 0 with an interrupt IN endpoint 0x81 large enough for a report.
    {
      libusb_config_descriptor* cfg = nullptr;
      int rc0 = libusb_get_active_config_descriptor(libusb_get_device(handle), &cfg);
      if (rc0 != 0) return fail("reading the configuration descriptor", rc0);
      std::string found_eps;
      bool ok = false;
      if (cfg->bNumInterfaces >= 1 && cfg->interface[0].num_altsetting >= 1) {
        const libusb_interface_descriptor& alt = cfg->interface[0].altsetting[0];
        for (int e = 0; e < alt.bNumEndpoints; ++e) {
          const libusb_endpoint_descriptor& ep = alt.endpoint[e];
          char b[48];
          std::snprintf(b, sizeof b, "%s0x%02x %s", found_eps.empty() ? "" : ", ", ep.bEndpointAddress,
                        (ep.bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_INTERRUPT ? "interrupt" : (ep.bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_BULK ? "bulk" : "other");
          found_eps += b;
          ok |= ep.bEndpointAddress == 0x81 && (ep.bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_INTERRUPT &&
                ep.wMaxPacketSize >= min_report_size(found);
        }
      }
      libusb_free_config_descriptor(cfg);
      if (!ok) {
        error = std::string("not the layout of a Rift tracker on ") + where + ": interface 0 has no interrupt IN endpoint 0x81 of " +
                std::to_string(min_report_size(found)) + "+ bytes (found: " + (found_eps.empty() ? "no endpoints" : found_eps) + ")";
        libusb_close(handle);
        handle = nullptr;
        return false;
      }
    }
    rc = libusb_kernel_driver_active(handle, 0);
    if (rc == 1) {
      if ((rc = libusb_detach_kernel_driver(handle, 0)) != 0) return fail("detaching the kernel driver", rc);
      detached_here = true;
      std::lock_guard<std::mutex> lock(mu);
      stats.kernel_driver_detached = true;
    } else if (rc < 0 && rc != LIBUSB_ERROR_NOT_SUPPORTED) {
      return fail("asking for the kernel driver", rc);
    }
    if ((rc = libusb_claim_interface(handle, 0)) != 0) return fail("claiming interface 0", rc);
    if (model == RiftModel::DK1) {
      rc = send_feature(dk1_config_report(command_id, kConfigUseCalibration | kConfigAutoCalibration, 0, opt.keep_alive_ms));
      if (rc < 0) return fail("sending the config report", rc);
    }
    if (!send_keep_alive()) return fail("sending the keep-alive report", LIBUSB_ERROR_IO);
    // A fresh device clock anchored at the first report after (re)connecting:
    // the counter may have restarted; the timeline carries on from the arrival.
    clock = std::make_unique<DeviceClock>(model == RiftModel::DK1 ? 16 : 32, model == RiftModel::DK1 ? 1'000'000'000 : 1'000'000);
    {
      std::lock_guard<std::mutex> lock(mu);  // report() reads it under the lock
      ++segment;
    }
    is_connected = true;
    streamed = chosen;  // (its address now: a serial-less tracker is looked for there first)
    streamed_before = true;
    const int want = std::max(1, opt.transfers_in_flight);
    transfers.clear();
    stalled.clear();
    for (int i = 0; i < want; ++i) {
      // Each transfer owns its buffer (freed with it): an abandoned transfer may still be written into.
      libusb_transfer* t = libusb_alloc_transfer(0);
      auto* buffer = static_cast<unsigned char*>(std::malloc(kRiftReportSize));
      if (!t || !buffer) {
        if (t) libusb_free_transfer(t);
        std::free(buffer);
        is_connected = false;
        release();
        error = std::string("out of memory for the transfers on ") + where;
        return false;
      }
      transfers.push_back(t);
      libusb_fill_interrupt_transfer(t, handle, 0x81, buffer, static_cast<int>(kRiftReportSize), on_transfer, this, 0);
      t->flags |= LIBUSB_TRANSFER_FREE_BUFFER;
      if ((rc = libusb_submit_transfer(t)) != 0) {
        is_connected = false;
        release();  // what was submitted comes back cancelled; the handle is closed
        error = std::string("submitting a transfer on ") + where + ": " + libusb_strerror(rc);
        return false;
      }
      flying.insert(t);
    }
    transfer_errors_in_a_row = 0;
    return true;
  }

  // After a loss: cancel the transfers and wait for every one to come back
  // (libusb completes a cancelled transfer, or one on a vanished device, with
  // a status), then free them and let go of the handle. A transfer is freed
  // only once it is back: freeing one libusb still holds lets it write into
  // freed memory. One the backend does not give back within a second is
  // abandoned: completed() frees it when it does come back (and does nothing
  // else with it), and its handle is closed once none is left.
  void release() {
    for (auto* t : flying) libusb_cancel_transfer(t);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (!flying.empty() && std::chrono::steady_clock::now() < deadline) {
      timeval tv{0, 20000};
      libusb_handle_events_timeout_completed(ctx, &tv, nullptr);
    }
    stalled.clear();  // back already: freed below with the rest
    for (auto* t : transfers) {
      if (flying.count(t)) abandoned.insert(t);
      else libusb_free_transfer(t);
    }
    transfers.clear();
    if (!flying.empty()) {
      {
        std::lock_guard<std::mutex> lock(mu);
        stats.transfers_abandoned += static_cast<int64_t>(flying.size());
      }
      event(StreamEvent::Kind::Disconnected,
            std::to_string(flying.size()) + " transfer(s) not back from libusb after 1 s; freed when they are");
      flying.clear();
      if (handle) abandoned_handles.push_back(handle);  // closing it would free what those transfers use
      handle = nullptr;
      return;
    }
    if (handle) {
      libusb_release_interface(handle, 0);
      libusb_close(handle);
      handle = nullptr;
    }
    close_abandoned_handles();
  }

  // The handles of earlier connections, once every transfer abandoned on them is back (never from a
  // transfer's callback: closing a handle there is not allowed).
  void close_abandoned_handles() {
    if (!abandoned.empty()) return;
    for (auto* h : abandoned_handles) libusb_close(h);
    abandoned_handles.clear();
  }
};

RiftStream::RiftStream(const RiftStreamOptions& o) : p_(std::make_unique<Impl>(o)) {
  if (!(o.max_pending_s > 0) || !std::isfinite(o.max_pending_s)) throw std::invalid_argument("max_pending_s must be > 0");
}

// One round of device service: events, keep-alive, reconnection.
void RiftStream::Impl::step(int timeout_ms) {
  if (handle || !flying.empty() || !abandoned.empty()) {
    timeval tv{timeout_ms / 1000, (timeout_ms % 1000) * 1000};
    libusb_handle_events_timeout_completed(ctx, &tv, nullptr);
    clear_stall();
    close_abandoned_handles();
  } else {
    std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
  }
  if (is_connected && now_s() - last_keep_alive_s >= opt.keep_alive_resend_s && !send_keep_alive())
    lost("the keep-alive could not be sent");
  if (!is_connected && ever_opened) {
    if (handle) release();
    if (now_s() - last_attempt_s >= opt.reconnect_every_s) {
      last_attempt_s = now_s();
      std::string err;
      if (connect(err)) {
        std::lock_guard<std::mutex> lock(mu);
        ++stats.reconnects;
        repeating_event_locked(StreamEvent::Kind::Reconnected, stats.reconnects, "streaming again");
      } else if (err.rfind("no Oculus Rift", 0) != 0) {  // found but refused: say why (an absent device says nothing new)
        std::lock_guard<std::mutex> lock(mu);
        ++stats.reconnect_failures;
        repeating_event_locked(StreamEvent::Kind::OpenFailed, stats.reconnect_failures, "reconnecting: " + err);
      }
    }
  }
}

RiftStream::~RiftStream() {
  if (p_->pump.joinable()) {
    p_->stop = true;
    p_->pump.join();
  }
  if (p_->ctx) {
    Impl& s = *p_;
    s.is_connected = false;
    s.release();
    // Abandoned transfers get one more second to come back; what still has not is left to the process.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (!s.abandoned.empty() && std::chrono::steady_clock::now() < deadline) {
      timeval tv{0, 20000};
      libusb_handle_events_timeout_completed(s.ctx, &tv, nullptr);
    }
    if (s.abandoned.empty()) {
      for (auto* h : s.abandoned_handles) libusb_close(h);
      libusb_exit(s.ctx);
    }
  }
}

bool RiftStream::choice_refused() const { return p_->choice_refused; }

bool RiftStream::open(std::string& error) {
  if (!p_->ctx) {
    const int rc = libusb_init(&p_->ctx);
    if (rc != 0) {
      p_->ctx = nullptr;
      error = std::string("USB is not available here: libusb could not start: ") + libusb_strerror(rc);
      return false;
    }
  }
  if (p_->pump.joinable()) return true;  // already streaming
  if (!p_->connect(error)) {
    p_->event(StreamEvent::Kind::OpenFailed, error);
    return false;
  }
  p_->ever_opened = true;
  p_->event(StreamEvent::Kind::Opened, p_->model == RiftModel::DK1 ? "Oculus Rift DK1" : "Oculus Rift DK2");
  if (p_->opt.background_thread)
    p_->pump = std::thread([s = p_.get()] {
      while (!s->stop) s->step(10);
    });
  return true;
}

void RiftStream::poll(int timeout_ms, std::vector<PoseSample>& out) {
  Impl& s = *p_;
  if (!s.ctx) return;
  if (s.pump.joinable()) {
    std::unique_lock<std::mutex> lock(s.mu);
    s.arrived.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return !s.pending.empty(); });
    out.insert(out.end(), s.pending.begin(), s.pending.end());
    s.pending.clear();
    return;
  }
  s.step(timeout_ms);
  std::lock_guard<std::mutex> lock(s.mu);
  out.insert(out.end(), s.pending.begin(), s.pending.end());
  s.pending.clear();
}

bool RiftStream::connected() const { return p_->is_connected; }
RiftModel RiftStream::model() const { return p_->model; }

StreamStats RiftStream::stats() const {
  std::lock_guard<std::mutex> lock(p_->mu);
  return p_->stats;
}

RiftStream::Snapshot RiftStream::snapshot() const {
  std::lock_guard<std::mutex> lock(p_->mu);
  return {p_->stats, p_->last};
}

PoseSample RiftStream::last_pose() const {
  std::lock_guard<std::mutex> lock(p_->mu);
  return p_->last;
}

int64_t RiftStream::now_ps() const { return p_->now_ps(); }

std::vector<StreamEvent> RiftStream::take_events() {
  std::lock_guard<std::mutex> lock(p_->mu);
  std::vector<StreamEvent> e;
  e.swap(p_->events);
  return e;
}

}  // namespace arp::tracker
