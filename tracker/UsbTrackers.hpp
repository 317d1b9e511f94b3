// Finding Oculus Rift DK1/DK2 trackers on USB through libusb-1.0
// (vendor 0x2833, product 0x0001 DK1, 0x0021 DK2), telling them apart (bus,
// address, serial number) and choosing one: by its serial number or its
// BUS:ADDR, or the only one attached -- never one of several silently.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "OculusReport.hpp"

struct libusb_device;  // libusb.h: typedef struct libusb_device libusb_device

namespace arp::tracker {

constexpr uint16_t kOculusVendor = 0x2833, kDk1Product = 0x0001, kDk2Product = 0x0021;

struct UsbTrackerInfo {
  RiftModel model = RiftModel::DK1;
  int bus = 0, address = 0;
  std::string serial;        // empty when it could not be read (no permission) or the device has none
  bool can_open = false;     // false: permission denied or busy (see `problem`)
  std::string problem;
};

struct UsbScan {
  bool usb_available = false;  // libusb could be initialised and list devices
  std::string usb_error;       // why not, when it could not
  int devices_seen = 0;        // every USB device, trackers or not
  std::vector<UsbTrackerInfo> trackers;
};

// Every tracker, each opened once to read its serial number and to see
// whether interface 0 is free (held by another program: can_open false).
UsbScan scan_usb_trackers();

// The trackers in a libusb device list (each opened to read its serial
// number; with probe_interface, also whether interface 0 can be claimed).
struct FoundTracker {
  UsbTrackerInfo info;
  libusb_device* device = nullptr;  // from the list: valid while the list is
};
std::vector<FoundTracker> find_trackers(libusb_device* const* list, long count, bool probe_interface);

// "DK1 bus 001 address 002 serial ARPSIM0001" -- what identifies a tracker to a person.
std::string describe(const UsbTrackerInfo& t);
// Whether a --device value names this tracker: its serial number, or BUS:ADDR in decimal ("1:2", "001:002").
bool selects(const std::string& device, const UsbTrackerInfo& t);
// Which tracker to stream: the one `device` names, or with `device` empty the
// only one attached. -1 and the reason (listing what is attached) when none
// matches or several do.
int choose_tracker(const std::vector<UsbTrackerInfo>& trackers, const std::string& device, std::string& why);
// Which tracker a reconnection takes: the one streamed `before`, however it was chosen (--device SERIAL or
// BUS:ADDR, or the only one). By its serial number when it had one -- a replug moves its address, and
// another tracker must not take its place. Without one (unreadable): the same model at the same address
// (its serial readable now or not), else the only serial-less tracker of that model attached (its new
// address). -1 and the reason otherwise.
int choose_again(const std::vector<UsbTrackerInfo>& trackers, const UsbTrackerInfo& before, std::string& why);

}  // namespace arp::tracker
