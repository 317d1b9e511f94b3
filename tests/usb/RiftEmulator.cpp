#include "RiftEmulator.hpp"

#include <linux/ioctl.h>
#include <linux/usbdevice_fs.h>
#include <umockdev.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <cstdio>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "tracker/RiftProtocol.hpp"
#include "tracker/SyntheticImu.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/UsbTrackers.hpp"

namespace arp::test {

namespace {

struct Urb {
  const void* client = nullptr;         // whose it is: each process opening the device is its own client
  UMockdevIoctlData* data = nullptr;    // the client's struct usbdevfs_urb (a reference we hold)
  UMockdevIoctlData* buffer = nullptr;  // its transfer buffer
  int type = 0, endpoint = 0, status = 0, actual = 0;
  bool withheld = false;  // withhold_transfers(): never completed until give_back()
};

void drop(Urb& u) {
  if (u.buffer) umockdev_ioctl_data_unref(u.buffer);
  if (u.data) umockdev_ioctl_data_unref(u.data);
  u.buffer = u.data = nullptr;
}

std::string descriptors_hex(tracker::RiftModel m, RiftEmulator::Layout layout) {
  const bool rift = layout == RiftEmulator::Layout::Rift;
  const uint16_t pid = m == tracker::RiftModel::DK1 ? tracker::kDk1Product : tracker::kDk2Product;
  const uint8_t d[] = {
      // device: USB 2.0, class per interface, 64-byte EP0, vendor 0x2833, product, one configuration
      // (strings: 1 manufacturer, 2 product, 3 serial number)
      18, 1, 0x00, 0x02, 0, 0, 0, 64, 0x33, 0x28, static_cast<uint8_t>(pid & 0xff), static_cast<uint8_t>(pid >> 8), 0x00, 0x01, 1, 2, 3, 1,
      // configuration: 34 bytes in all, one interface
      9, 2, 34, 0, 1, 1, 0, 0x80, 50,
      // interface 0: HID, one endpoint
      9, 4, 0, 0, 1, 3, 0, 0, 0,
      // HID descriptor
      9, 0x21, 0x11, 0x01, 0, 1, 0x22, 0x40, 0x00,
      // endpoint 0x81: interrupt IN, 64 bytes, every 1 ms (or, not a Rift: bulk OUT 0x02)
      7, 5, static_cast<uint8_t>(rift ? 0x81 : 0x02), static_cast<uint8_t>(rift ? 3 : 2), 64, 0, 1};
  std::string s;
  char b[3];
  for (uint8_t x : d) {
    std::snprintf(b, sizeof b, "%02x", x);
    s += b;
  }
  return s;
}

// A string descriptor: index 0 is the language list (US English), then UTF-16LE text.
std::vector<uint8_t> string_descriptor(int index, const std::string& serial, tracker::RiftModel m) {
  if (index == 0) return {4, 3, 0x09, 0x04};
  const std::string text = index == 1   ? "Oculus VR, Inc."
                           : index == 2 ? (m == tracker::RiftModel::DK1 ? "Tracker DK" : "Rift DK2")
                           : index == 3 ? serial
                                        : "";
  if (text.empty()) return {};
  std::vector<uint8_t> d{static_cast<uint8_t>(2 + 2 * text.size()), 3};
  for (char c : text) {
    d.push_back(static_cast<uint8_t>(c));
    d.push_back(0);
  }
  return d;
}

// One testbed for every emulator alive (umockdev's preload library reads one
// testbed directory), made with the first and freed with the last.
std::mutex g_testbed_mu;
UMockdevTestbed* g_testbed = nullptr;
int g_testbed_users = 0;

UMockdevTestbed* acquire_testbed() {
  std::lock_guard<std::mutex> lock(g_testbed_mu);
  if (g_testbed_users++ == 0) g_testbed = umockdev_testbed_new();
  return g_testbed;
}

void release_testbed() {
  std::lock_guard<std::mutex> lock(g_testbed_mu);
  if (--g_testbed_users == 0) g_clear_object(&g_testbed);
}

}  // namespace

struct RiftEmulator::State {
  tracker::RiftModel model;
  RiftEmulator::Identity id;
  std::string syspath, devnode;
  std::vector<std::array<uint8_t, tracker::kRiftReportSize>> reports;
  UMockdevTestbed* testbed = nullptr;
  UMockdevIoctlBase* handler = nullptr;
  mutable std::mutex mu;
  bool connected = true, detached = false, claimed = false, claimed_elsewhere = false, halted = false;
  int64_t clear_halt_count = 0;
  int cut_remaining = 0;        // reports still to cut short
  int fail_remaining = 0, fail_error = 0;  // fail_transfers()
  size_t report_length = tracker::kRiftReportSize;
  int claimed_count_next = 0;   // > 0: the next report's sample count
  uint64_t counter_shift = 0;   // added to every timestamp from now on (a restart), modulo the counter's width
  std::deque<Urb> done, interrupts;
  std::vector<std::vector<uint8_t>> features;
  int64_t sent = 0;
  const ManualClock* clock = nullptr;  // the test's, or the wall clock
  uintptr_t live_id = 0;               // in g_live (the ioctl handler's data)
  int64_t streaming_since_ps = 0;
  bool streaming = false;
  int64_t delivered_at_start = 0;
  int64_t keep_alive_until_ps = 0;
  int64_t deliver_from_ps = 0;  // nothing is handed over before this (delay_delivery)
  int64_t transport_per_s = 0;  // > 0: at most this many reports a second are handed over (slow_transport)
  bool drained = false;         // a reap found nothing since the last report handed over
  bool withholding_new = false;  // withhold_transfers() until replug(): new submissions are withheld too

  int64_t now_ps() const {
    if (clock) return clock->now_ps();
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - kEpoch).count() * 1000;
  }
  static inline const std::chrono::steady_clock::time_point kEpoch = std::chrono::steady_clock::now();

  // Reports due by `now`: one every millisecond from the first keep-alive, while the keep-alive holds
  // (the reports a keep-alive that ran out left unsent are not owed).
  int64_t due(int64_t now) const {
    if (!streaming || now < deliver_from_ps) return sent;
    const int64_t until = std::min(now, keep_alive_until_ps);
    if (until < streaming_since_ps) return sent;
    int64_t owed = delivered_at_start + (until - streaming_since_ps) / 1'000'000'000 + 1;
    if (transport_per_s > 0) {  // the rest wait: the device's time falls ever further behind the host's
      constexpr int64_t kSecondPs = 1'000'000'000'000;
      const int64_t t = until - streaming_since_ps;  // (whole seconds, then the rest: no product past int64)
      owed = std::min(owed, delivered_at_start + t / kSecondPs * transport_per_s + t % kSecondPs * transport_per_s / kSecondPs + 1);
    }
    return std::max(sent, std::min(owed, static_cast<int64_t>(reports.size())));
  }
  bool report_due(int64_t now) const { return sent < due(now); }

  bool dk1() const { return model == tracker::RiftModel::DK1; }
  uint64_t timestamp_of(const std::array<uint8_t, tracker::kRiftReportSize>& r) const {
    if (dk1()) return static_cast<uint64_t>(r[2] | (r[3] << 8));
    return static_cast<uint64_t>(r[8]) | (static_cast<uint64_t>(r[9]) << 8) | (static_cast<uint64_t>(r[10]) << 16) |
           (static_cast<uint64_t>(r[11]) << 24);
  }
  // A report as sent after the quirks asked for (raw bytes: the counts and
  // timestamps a real device may send, which encode_report would refuse).
  std::array<uint8_t, tracker::kRiftReportSize> quirked(std::array<uint8_t, tracker::kRiftReportSize> r) {
    const uint64_t ts = (timestamp_of(r) + counter_shift) & (dk1() ? 0xffffu : 0xffffffffu);
    if (dk1()) {
      r[2] = static_cast<uint8_t>(ts);
      r[3] = static_cast<uint8_t>(ts >> 8);
    } else {
      for (int i = 0; i < 4; ++i) r[8 + static_cast<size_t>(i)] = static_cast<uint8_t>(ts >> (8 * i));
    }
    if (claimed_count_next > 0) {
      const size_t at = dk1() ? 8 : 12, held = dk1() ? 3 : 2;
      for (size_t k = held - 1; k > 0; --k) std::memcpy(&r[at + 16 * k], &r[at], 16);  // the report's own sample, latest slot too
      r[dk1() ? 1 : 3] = static_cast<uint8_t>(claimed_count_next);
      claimed_count_next = 0;
    }
    return r;
  }

  gboolean handle(UMockdevIoctlClient* client) {
    std::lock_guard<std::mutex> lock(mu);
    const gulong request = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
    auto reply = [&](int result, int err) {
      umockdev_ioctl_client_complete(client, result, err);
      return TRUE;
    };
    if (!connected && request != USBDEVFS_REAPURB && request != USBDEVFS_REAPURBNDELAY && request != USBDEVFS_DISCARDURB &&
        request != USBDEVFS_RELEASEINTERFACE)
      return reply(-1, ENODEV);
    switch (request) {
      case USBDEVFS_GET_CAPABILITIES: {
        UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), nullptr);
        *reinterpret_cast<guint32*>(d->data) = USBDEVFS_CAP_REAP_AFTER_DISCONNECT;
        umockdev_ioctl_data_unref(d);
        return reply(0, 0);
      }
      case USBDEVFS_GETDRIVER: {
        if (detached && !claimed_elsewhere) return reply(-1, ENODATA);
        UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_getdriver), nullptr);
        // Another program streaming through libusb shows as the usbfs driver.
        std::strcpy(reinterpret_cast<usbdevfs_getdriver*>(d->data)->driver, claimed_elsewhere ? "usbfs" : "usbhid");
        umockdev_ioctl_data_unref(d);
        return reply(0, 0);
      }
      case USBDEVFS_IOCTL: {  // detach (and re-attach) the kernel driver
        UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_ioctl), nullptr);
        const int code = reinterpret_cast<usbdevfs_ioctl*>(d->data)->ioctl_code;
        umockdev_ioctl_data_unref(d);
        if (code == static_cast<int>(USBDEVFS_DISCONNECT)) {
          if (detached) return reply(-1, ENODATA);
          detached = true;
          return reply(0, 0);
        }
        if (code == static_cast<int>(USBDEVFS_CONNECT)) {
          detached = false;
          return reply(0, 0);
        }
        return reply(-1, ENOTTY);
      }
      case USBDEVFS_CLAIMINTERFACE:
        if (!detached || claimed_elsewhere) return reply(-1, EBUSY);  // usbhid, or another program, has it
        claimed = true;
        return reply(0, 0);
      case USBDEVFS_RELEASEINTERFACE:
        claimed = false;
        return reply(0, 0);
      case USBDEVFS_CLEAR_HALT:
        halted = false;
        ++clear_halt_count;
        return reply(0, 0);
      case USBDEVFS_SUBMITURB: {
        Urb u;
        u.client = client;
        u.data = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
        const auto* urb = reinterpret_cast<const usbdevfs_urb*>(u.data->data);
        u.type = urb->type;
        u.endpoint = urb->endpoint;
        u.buffer = umockdev_ioctl_data_resolve(u.data, offsetof(usbdevfs_urb, buffer), static_cast<gsize>(urb->buffer_length), nullptr);
        if (u.type == USBDEVFS_URB_TYPE_CONTROL) {
          const uint8_t* setup = u.buffer->data;
          const int length = setup[6] | (setup[7] << 8);
          if (setup[0] == tracker::kHidRequestTypeOut && setup[1] == tracker::kHidSetReport && (setup[3] == 3)) {
            std::vector<uint8_t> rep(setup + 8, setup + 8 + length);
            if (!rep.empty() && (rep[0] == tracker::kDk1KeepAliveReport || rep[0] == tracker::kDk2KeepAliveReport) && rep.size() >= 5) {
              const int interval = rep[rep.size() - 2] | (rep[rep.size() - 1] << 8);
              const int64_t now = now_ps();
              keep_alive_until_ps = now + int64_t{interval} * 1'000'000'000;
              if (!streaming) {
                streaming = true;
                streaming_since_ps = now;
                delivered_at_start = sent;
              }
            }
            features.push_back(std::move(rep));
            u.actual = length;
          } else if (setup[0] == 0x80 && setup[1] == 6 && setup[3] == 3) {  // GET_DESCRIPTOR (string)
            const std::vector<uint8_t> d = string_descriptor(setup[2], id.serial, model);
            if (d.empty()) {
              u.status = -EPIPE;
            } else {
              u.actual = std::min(length, static_cast<int>(d.size()));
              std::memcpy(u.buffer->data + 8, d.data(), static_cast<size_t>(u.actual));
            }
          } else {
            u.status = -EPIPE;  // anything else stalls
          }
          done.push_back(u);
          return reply(0, 0);
        }
        if (u.type == USBDEVFS_URB_TYPE_INTERRUPT && u.endpoint == 0x81) {
          u.withheld = withholding_new;
          interrupts.push_back(u);
          return reply(0, 0);
        }
        drop(u);
        return reply(-1, EINVAL);
      }
      case USBDEVFS_DISCARDURB: {
        const gulong addr = *reinterpret_cast<const gulong*>(arg->data);
        for (auto it = interrupts.begin(); it != interrupts.end(); ++it)
          if (it->client == client && it->data->client_addr == addr) {
            if (it->withheld) return reply(0, 0);  // accepted, never completed (until give_back)
            Urb u = *it;
            interrupts.erase(it);
            u.status = -ENOENT;
            done.push_back(u);
            return reply(0, 0);
          }
        return reply(-1, EINVAL);
      }
      case USBDEVFS_REAPURB:
      case USBDEVFS_REAPURBNDELAY: {
        // Only this client's transfers: a process that went away may have left some behind.
        Urb u;
        const int64_t now = now_ps();
        auto mine = [client](std::deque<Urb>& q) {
          for (auto it = q.begin(); it != q.end(); ++it)
            if (it->client == client && !it->withheld) return it;
          return q.end();
        };
        const bool withholding = std::any_of(interrupts.begin(), interrupts.end(), [client](const Urb& w) { return w.client == client && w.withheld; });
        const auto d = mine(done);
        const auto i = mine(interrupts);
        if (d != done.end()) {
          u = *d;
          done.erase(d);
        } else if (connected && halted && i != interrupts.end()) {
          u = *i;  // a halted endpoint fails every transfer until the halt is cleared
          interrupts.erase(i);
          u.status = -EPIPE;
        } else if (connected && fail_remaining > 0 && i != interrupts.end()) {
          u = *i;  // a transfer error
          interrupts.erase(i);
          u.status = -fail_error;
          --fail_remaining;
        } else if (!connected && i != interrupts.end()) {
          u = *i;  // unplugged: what was in flight comes back failed
          interrupts.erase(i);
          u.status = -ENODEV;
        } else if (connected && i != interrupts.end() && report_due(now)) {
          u = *i;
          interrupts.erase(i);
          const auto rep = quirked(reports[static_cast<size_t>(sent++)]);
          u.actual = cut_remaining > 0 ? 10 : static_cast<int>(report_length);
          if (cut_remaining > 0) --cut_remaining;
          drained = false;
          std::memcpy(u.buffer->data, rep.data(), static_cast<size_t>(u.actual));
        } else {
          drained = true;
          // A client with withheld transfers is not told the device is gone (libusb would complete them itself).
          return reply(-1, connected || withholding ? EAGAIN : ENODEV);
        }
        auto* urb = reinterpret_cast<usbdevfs_urb*>(u.data->data);
        urb->status = u.status;
        urb->actual_length = u.actual;
        UMockdevIoctlData* ptr = umockdev_ioctl_data_resolve(arg, 0, sizeof(gpointer), nullptr);
        umockdev_ioctl_data_set_ptr(ptr, 0, u.data);
        umockdev_ioctl_data_unref(ptr);
        umockdev_ioctl_client_complete(client, 0, 0);
        drop(u);
        return TRUE;
      }
      default:
        return FALSE;
    }
  }
};

namespace {
// The emulators alive, and how many ioctls each is answering: umockdev answers on its own thread, and a
// call already under way when an emulator is destroyed must neither start on its State nor be cut off.
// The handler's data is the emulator's id, never reused (a State that is gone is never touched, and a new
// one at the same address is not taken for it).
struct Live {
  RiftEmulator::State* state;
  int calls;
};
std::mutex g_live_mu;
std::condition_variable g_live_cv;
std::map<uintptr_t, Live> g_live;
uintptr_t g_next_id = 1;

gboolean on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer data) {
  const auto id = reinterpret_cast<uintptr_t>(data);
  RiftEmulator::State* s = nullptr;
  {
    std::lock_guard<std::mutex> lock(g_live_mu);
    const auto it = g_live.find(id);
    if (it == g_live.end()) {  // being destroyed: the device is gone (unanswered, the caller would wait for ever)
      umockdev_ioctl_client_complete(client, -1, ENODEV);
      return TRUE;
    }
    ++it->second.calls;
    s = it->second.state;
  }
  const gboolean handled = s->handle(client);
  std::lock_guard<std::mutex> lock(g_live_mu);
  --g_live[id].calls;
  g_live_cv.notify_all();
  return handled;
}

uintptr_t remember(RiftEmulator::State* s) {
  std::lock_guard<std::mutex> lock(g_live_mu);
  const uintptr_t id = g_next_id++;
  g_live[id] = {s, 0};
  return id;
}

// Takes an emulator out of g_live and waits for the ioctls it is answering.
void forget(uintptr_t id) {
  std::unique_lock<std::mutex> lock(g_live_mu);
  g_live_cv.wait(lock, [id] { return g_live[id].calls == 0; });
  g_live.erase(id);
}
}  // namespace

std::vector<tracker::PoseSample> yaw_90(double seconds) {
  tracker::SamplingSpec s;
  s.rate_hz = 1000;
  s.duration_s = seconds;
  return tracker::constant_rotation({0, 1, 0}, 90.0, s);
}

RiftEmulator::RiftEmulator(tracker::RiftModel model, std::vector<tracker::PoseSample> truth, Layout layout)
    : RiftEmulator(model, std::move(truth), layout, Identity{}) {}

RiftEmulator::RiftEmulator(tracker::RiftModel model, std::vector<tracker::PoseSample> truth, Layout layout, Identity id)
    : s_(std::make_unique<State>()) {
  if (id.address < 2 || id.address > 127) throw std::invalid_argument("a USB address for the emulator is 2..127");
  s_->model = model;
  s_->id = id;
  // The IMU readings of the motion, as reports with one sample each; the
  // counters start just before they wrap.
  const auto imu = tracker::synthesize_imu(truth, tracker::ImuNoise{});
  for (size_t k = 0; k < imu.size(); ++k) {
    tracker::ImuReport r;
    r.model = model;
    r.sample_count = 1;
    r.timestamp = model == tracker::RiftModel::DK1 ? static_cast<uint32_t>((65000 + k) & 0xffff)
                                                   : static_cast<uint32_t>(4294767296ull + k * 1000ull);
    r.samples_since_start = static_cast<uint16_t>(k);
    r.temperature = 2500;
    for (int a = 0; a < 3; ++a) {
      r.samples[0].gyro[static_cast<size_t>(a)] = static_cast<int32_t>(std::lround(imu[k].gyro[a] * 1e4));
      r.samples[0].accel[static_cast<size_t>(a)] = static_cast<int32_t>(std::lround(imu[k].accel[a] * 1e4));
      r.magnetometer[static_cast<size_t>(a)] = static_cast<int16_t>(std::lround(imu[k].mag[a] * 1e4));  // 1e-4 gauss
    }
    s_->reports.push_back(tracker::encode_report(r));
  }
  char num[8];
  std::snprintf(num, sizeof num, "%03d", id.address);
  s_->devnode = std::string("/dev/bus/usb/001/") + num;
  s_->syspath = "/sys/devices/pci0000:00/usb1/1-" + std::to_string(id.address - 1);
  s_->testbed = acquire_testbed();
  s_->handler = umockdev_ioctl_base_new();
  s_->live_id = remember(s_.get());
  g_signal_connect_after(s_->handler, "handle-ioctl", G_CALLBACK(on_ioctl), reinterpret_cast<gpointer>(s_->live_id));
  GError* err = nullptr;
  if (!umockdev_testbed_attach_ioctl(s_->testbed, s_->devnode.c_str(), s_->handler, &err)) {
    forget(s_->live_id);
    g_clear_object(&s_->handler);
    release_testbed();
    throw std::runtime_error(std::string("umockdev: ") + (err ? err->message : "cannot attach the ioctl handler"));
  }
  const std::string dev = "P: " + s_->syspath.substr(4) + "\n" + "N: bus/usb/001/" + num + "\n" +
                          "E: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\nE: DRIVER=usb\nE: BUSNUM=001\nE: DEVNUM=" + num + "\n" +
                          "E: DEVNAME=" + s_->devnode + "\n" +
                          "A: busnum=1\\n\nA: devnum=" + std::to_string(id.address) + "\\n\nA: speed=12\\n\nA: bConfigurationValue=1\\n\n" +
                          "A: idVendor=2833\\n\nA: idProduct=" + std::string(model == tracker::RiftModel::DK1 ? "0001" : "0021") + "\\n\n" +
                          "A: serial=" + id.serial + "\\n\n" + "H: descriptors=" + descriptors_hex(model, layout) + "\n";
  if (!umockdev_testbed_add_from_string(s_->testbed, dev.c_str(), &err)) {
    forget(s_->live_id);
    umockdev_testbed_detach_ioctl(s_->testbed, s_->devnode.c_str(), nullptr);
    g_clear_object(&s_->handler);
    release_testbed();
    throw std::runtime_error(std::string("umockdev: ") + (err ? err->message : "cannot add the device"));
  }
}

RiftEmulator::~RiftEmulator() {
  forget(s_->live_id);  // no ioctl reaches this State from now on
  umockdev_testbed_remove_device(s_->testbed, s_->syspath.c_str());
  umockdev_testbed_detach_ioctl(s_->testbed, s_->devnode.c_str(), nullptr);
  g_signal_handlers_disconnect_by_data(s_->handler, reinterpret_cast<gpointer>(s_->live_id));
  g_clear_object(&s_->handler);
  for (auto& u : s_->done) drop(u);
  for (auto& u : s_->interrupts) drop(u);
  s_->testbed = nullptr;
  release_testbed();
}

// fn(State&) under the state's lock: the ioctl handler works on it on umockdev's thread.
template <class F>
auto RiftEmulator::locked(F&& fn) const {
  std::lock_guard<std::mutex> lock(s_->mu);
  return fn(*s_);
}

void RiftEmulator::jump_counter(int64_t ticks) {
  locked([&](State& s) { s.counter_shift += static_cast<uint64_t>(ticks); });
}
void RiftEmulator::slow_transport(int reports_per_s) {
  if (reports_per_s < 0 || reports_per_s > 1'000'000) throw std::invalid_argument("slow_transport: 0 .. 1000000 reports a second");
  locked([&](State& s) { s.transport_per_s = reports_per_s; });
}

void RiftEmulator::delay_delivery(int64_t ms) {
  locked([&](State& s) { s.deliver_from_ps = s.now_ps() + ms * 1'000'000'000; });
}
void RiftEmulator::drive_by(const ManualClock& clock) {
  locked([&](State& s) { s.clock = &clock; });
}
bool RiftEmulator::host_drained() const {
  return locked([](const State& s) { return s.drained; });
}
int64_t RiftEmulator::reports_due() const {
  return locked([](const State& s) { return s.due(s.now_ps()); });
}
void RiftEmulator::unplug() {
  locked([](State& s) { s.connected = s.claimed = false; });
}
void RiftEmulator::replug() {
  locked([](State& s) {
    s.connected = true;
    s.detached = false;         // the kernel binds usbhid again
    s.streaming = false;        // until the next keep-alive
    s.withholding_new = false;
  });
}
void RiftEmulator::inject_malformed_report(int n) {
  locked([&](State& s) { s.cut_remaining += n; });
}
void RiftEmulator::set_report_length(size_t bytes) {
  if (bytes > tracker::kRiftReportSize) throw std::invalid_argument("a Rift report is at most 64 bytes");
  locked([&](State& s) { s.report_length = bytes; });
}
void RiftEmulator::inject_sample_count(int count) {
  if (count < 1 || count > 255) throw std::invalid_argument("a sample count is 1..255");
  locked([&](State& s) { s.claimed_count_next = count; });
}
void RiftEmulator::withhold_transfers() {
  locked([](State& s) {
    for (auto& u : s.interrupts) u.withheld = true;
    s.withholding_new = true;
  });
}
void RiftEmulator::give_back() {
  locked([](State& s) {
    for (auto it = s.interrupts.begin(); it != s.interrupts.end();) {
      if (!it->withheld) {
        ++it;
        continue;
      }
      Urb u = *it;
      it = s.interrupts.erase(it);
      u.withheld = false;
      u.status = -ENOENT;  // cancelled
      s.done.push_back(u);
    }
  });
}
void RiftEmulator::fail_transfers(int n, int error) {
  locked([&](State& s) {
    s.fail_remaining = n;
    s.fail_error = error;
  });
}
void RiftEmulator::stall() {
  locked([](State& s) { s.halted = true; });
}
void RiftEmulator::hold_interface_elsewhere() {
  locked([](State& s) { s.claimed_elsewhere = s.detached = true; });  // the other program took it from usbhid
}
int64_t RiftEmulator::clear_halts() const {
  return locked([](const State& s) { return s.clear_halt_count; });
}
void RiftEmulator::restart_counter() {
  locked([](State& s) {
    if (s.sent >= static_cast<int64_t>(s.reports.size())) return;
    // The next report's timestamp becomes 0.
    s.counter_shift = (~s.timestamp_of(s.reports[static_cast<size_t>(s.sent)])) + 1;
  });
}
std::vector<std::vector<uint8_t>> RiftEmulator::feature_reports() const {
  return locked([](const State& s) { return s.features; });
}
int64_t RiftEmulator::reports_sent() const {
  return locked([](const State& s) { return s.sent; });
}
bool RiftEmulator::kernel_driver_detached() const {
  return locked([](const State& s) { return s.detached; });
}
bool RiftEmulator::interface_claimed() const {
  return locked([](const State& s) { return s.claimed; });
}

}  // namespace arp::test
