#include "UsbTrackers.hpp"

#include <libusb-1.0/libusb.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace arp::tracker {

namespace {

bool decimal(const std::string& s, int& v) {
  if (s.empty() || s.size() > 3) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  v = std::atoi(s.c_str());
  return true;
}

std::string list_of(const std::vector<UsbTrackerInfo>& ts) {
  std::string s;
  for (const auto& t : ts) s += (s.empty() ? "" : "; ") + describe(t);
  return s;
}

}  // namespace

std::vector<FoundTracker> find_trackers(libusb_device* const* list, long count, bool probe_interface) {
  std::vector<FoundTracker> out;
  for (long i = 0; i < count; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0 || d.idVendor != kOculusVendor) continue;
    if (d.idProduct != kDk1Product && d.idProduct != kDk2Product) continue;
    FoundTracker f;
    f.device = list[i];
    UsbTrackerInfo& t = f.info;
    t.model = d.idProduct == kDk1Product ? RiftModel::DK1 : RiftModel::DK2;
    t.bus = libusb_get_bus_number(list[i]);
    t.address = libusb_get_device_address(list[i]);
    libusb_device_handle* h = nullptr;
    const int orc = libusb_open(list[i], &h);
    if (orc == LIBUSB_ERROR_NO_DEVICE) continue;  // unplugged while the list was read: not there
    if (orc == 0) {
      t.can_open = true;
      unsigned char serial[128] = {};
      const int src = d.iSerialNumber != 0 ? libusb_get_string_descriptor_ascii(h, d.iSerialNumber, serial, sizeof serial - 1) : 0;
      if (src == LIBUSB_ERROR_NO_DEVICE) {  // going away: not there
        libusb_close(h);
        continue;
      }
      if (src > 0) t.serial = reinterpret_cast<const char*>(serial);
      // Bound to usbhid (as a Rift is when nothing streams it) is normal: streaming detaches it.
      // Not bound and not claimable: another program (a tracker tool, another arpsim) holds it.
      if (probe_interface && libusb_kernel_driver_active(h, 0) == 0) {
        const int crc = libusb_claim_interface(h, 0);
        if (crc == 0) {
          libusb_release_interface(h, 0);
        } else {
          t.can_open = false;
          t.problem = crc == LIBUSB_ERROR_BUSY ? "in use by another program (interface 0 is claimed)"
                                               : std::string("interface 0 cannot be claimed: ") + libusb_strerror(crc);
        }
      }
      libusb_close(h);
    } else if (orc == LIBUSB_ERROR_ACCESS) {
      t.problem = "permission denied: install scripts/udev/70-arpsim-oculus.rules (docs/tracker.md)";
    } else {
      t.problem = std::string("cannot open: ") + libusb_strerror(orc);
    }
    out.push_back(f);
  }
  // In bus and address order, whatever order the system listed them in: a list a person can compare.
  std::sort(out.begin(), out.end(), [](const FoundTracker& a, const FoundTracker& b) {
    return a.info.bus != b.info.bus ? a.info.bus < b.info.bus : a.info.address < b.info.address;
  });
  return out;
}

UsbScan scan_usb_trackers() {
  UsbScan scan;
  libusb_context* ctx = nullptr;
  const int rc = libusb_init(&ctx);
  if (rc != 0) {
    scan.usb_error = std::string("libusb could not start: ") + libusb_strerror(rc);
    return scan;
  }
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &list);
  if (n < 0) {
    scan.usb_error = std::string("libusb could not list devices: ") + libusb_strerror(static_cast<int>(n));
    libusb_exit(ctx);
    return scan;
  }
  scan.usb_available = true;
  scan.devices_seen = static_cast<int>(n);
  for (const FoundTracker& f : find_trackers(list, static_cast<long>(n), true)) scan.trackers.push_back(f.info);
  libusb_free_device_list(list, 1);
  libusb_exit(ctx);
  return scan;
}

std::string describe(const UsbTrackerInfo& t) {
  char b[96];
  std::snprintf(b, sizeof b, "%s bus %03d address %03d", t.model == RiftModel::DK1 ? "DK1" : "DK2", t.bus, t.address);
  return std::string(b) + (t.serial.empty() ? " (serial unread)" : " serial " + t.serial);
}

bool selects(const std::string& device, const UsbTrackerInfo& t) {
  if (!t.serial.empty() && device == t.serial) return true;
  const size_t colon = device.find(':');
  int bus = 0, address = 0;
  return colon != std::string::npos && decimal(device.substr(0, colon), bus) && decimal(device.substr(colon + 1), address) &&
         bus == t.bus && address == t.address;
}

int choose_tracker(const std::vector<UsbTrackerInfo>& ts, const std::string& device, std::string& why) {
  if (ts.empty()) {
    why = "no Oculus Rift DK1/DK2 on USB (vendor 0x2833, products 0x0001/0x0021)";
    return -1;
  }
  if (device.empty()) {
    if (ts.size() == 1) return 0;
    why = std::to_string(ts.size()) + " trackers attached (" + list_of(ts) + "): choose one with --device SERIAL or --device BUS:ADDR";
    return -1;
  }
  for (size_t i = 0; i < ts.size(); ++i)
    if (selects(device, ts[i])) return static_cast<int>(i);
  why = "no tracker is '" + device.substr(0, 64) + "' (attached: " + list_of(ts) + ")";
  return -1;
}

int choose_again(const std::vector<UsbTrackerInfo>& ts, const UsbTrackerInfo& before, std::string& why) {
  const std::string attached = ts.empty() ? "none" : list_of(ts);
  if (!before.serial.empty()) {
    for (size_t i = 0; i < ts.size(); ++i)
      if (ts[i].serial == before.serial) return static_cast<int>(i);
    why = "waiting for the tracker streamed before (serial " + before.serial + "): attached: " + attached;
    return -1;
  }
  std::vector<int> candidates;
  for (size_t i = 0; i < ts.size(); ++i) {
    if (ts[i].model != before.model) continue;
    // At its address it is taken whether its serial reads now or not (a read can fail once, at one open).
    if (ts[i].bus == before.bus && ts[i].address == before.address) return static_cast<int>(i);
    if (ts[i].serial.empty()) candidates.push_back(static_cast<int>(i));
  }
  if (candidates.size() == 1) return candidates[0];
  why = "waiting for the tracker streamed before (" + describe(before) + "; without a serial number it is known by its model, " +
        (candidates.empty() ? std::string("and none of that model without one is attached")
                            : std::to_string(candidates.size()) + " of that model without one are attached and cannot be told apart") +
        "): attached: " + attached;
  return -1;
}

}  // namespace arp::tracker
