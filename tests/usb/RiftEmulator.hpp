// An Oculus Rift DK1 or DK2 IMU emulated in user space with umockdev (tests
// only): a sysfs device with the Rift's descriptors, and an ioctl handler
// standing in for the kernel's usbdevfs -- kernel-driver query and detach,
// interface claim, HID feature reports (recorded), interrupt IN transfers on
// 0x81 answered at 1000 reports per second of wall time with reports encoded
// from a synthetic head motion (gyroscope, accelerometer and the earth's
// field on the magnetometer, tracker/SyntheticImu; the DK1's 16-bit millisecond counter starts
// just before its wrap), the device stopping when its keep-alive runs out,
// and on request: malformed reports, 62-byte reports, a sample count larger
// than a report holds, a restarted counter, unplugging and replugging. Each
// device has a bus address and a serial number (its string descriptor 3);
// several emulators alive at once are several devices on one bus.
//
// Its time is the wall clock, or a ManualClock the test advances (drive_by):
// reports are then due one per millisecond of that clock and the keep-alive
// runs out on it, and the stream under test reads the same clock
// (RiftStreamOptions::host_clock), so what a test checks does not depend on
// how fast the machine runs.
//
// The process (and any child it starts) must run under umockdev's preload
// library (ctest runs the USB tests through umockdev-wrapper).
#pragma once
#include <cstddef>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tracker/OculusReport.hpp"
#include "tracker/PoseSample.hpp"

namespace arp::test {

// The motion the USB tests' devices follow: a yaw at 90 deg/s, sampled at 1 kHz for `seconds`.
std::vector<tracker::PoseSample> yaw_90(double seconds);

// A clock only the test moves (ps; thread-safe: the stream's pump and umockdev's thread read it).
class ManualClock {
 public:
  int64_t now_ps() const { return ps_.load(); }
  void advance_ps(int64_t ps) { ps_ += ps; }
  // For RiftStreamOptions::host_clock (the clock must outlive the stream).
  std::function<int64_t()> function() const {
    return [this] { return now_ps(); };
  }

 private:
  std::atomic<int64_t> ps_{0};
};

class RiftEmulator {
 public:
  enum class Layout { Rift, NoInterruptIn };  // NoInterruptIn: interface 0's one endpoint is bulk OUT 0x02
  struct Identity {
    int address = 2;                    // on bus 001; 2..127, one per emulator alive
    std::string serial = "ARPSIM0001";  // ASCII
  };
  // truth: the head motion the IMU follows (samples with angular velocity, 1 kHz or finer).
  RiftEmulator(tracker::RiftModel model, std::vector<tracker::PoseSample> truth, Layout layout = Layout::Rift);
  RiftEmulator(tracker::RiftModel model, std::vector<tracker::PoseSample> truth, Layout layout, Identity id);
  ~RiftEmulator();

  // From now on the device's time is `clock` (it must outlive the emulator), not the wall clock.
  void drive_by(const ManualClock& clock);
  // Reports the device would have sent by now (its clock, its keep-alive): with reports_sent(), whether a
  // driven device has delivered all it owes.
  int64_t reports_due() const;
  // Whether the host has asked for a report since the last one it was given and found none: its USB event
  // loop has then returned to the driver (libusb reaps until nothing is left), which does its own work
  // (keep-alive, halts) before asking again.
  bool host_drained() const;

  void unplug();
  void replug();
  void inject_malformed_report(int n = 1);  // the next n reports are cut short (10 bytes)
  // The devices' quirks, for the reports sent from now on:
  void set_report_length(size_t bytes);      // a DK1 may send 62 bytes instead of 64
  void inject_sample_count(int count);       // the next report claims `count` samples (its own is the latest)
  void restart_counter();                    // the device restarts: its timestamp counter starts again at 0
  void jump_counter(int64_t ticks);          // the timestamp counter steps forward by `ticks` (a glitch)
  // The host is busy: reports owed during the next `ms` of the device's clock are handed over together
  // when it has passed (a burst, as queued transfers complete).
  void delay_delivery(int64_t ms);
  // A transport slower than the device (what an emulator starved of CPU is): at most `reports_per_s`
  // reports a second are handed over, the others wait in order, so the device's time falls ever further
  // behind the host's. 0: none held back.
  void slow_transport(int reports_per_s);
  // A hung host controller: the interrupt transfers in flight now, and those submitted until replug(), are
  // never completed -- not by a report, not when discarded, not when unplugged -- until give_back()
  // completes them as cancelled.
  void withhold_transfers();
  void give_back();
  // The next n interrupt transfers fail with usbfs status -error (ETIME: the host controller timed out;
  // EPROTO: a bus error), each at once and without a report.
  void fail_transfers(int n, int error);
  void stall();                              // endpoint 0x81 halts: transfers fail (EPIPE) until a CLEAR_HALT
  void hold_interface_elsewhere();           // another program detached usbhid and claimed interface 0 (EBUSY)
  int64_t clear_halts() const;
  // Feature reports received (each as sent: report id first).
  std::vector<std::vector<uint8_t>> feature_reports() const;
  int64_t reports_sent() const;
  bool kernel_driver_detached() const;
  bool interface_claimed() const;

  struct State;

 private:
  template <class F>
  auto locked(F&& fn) const;
  std::unique_ptr<State> s_;
};

}  // namespace arp::test
