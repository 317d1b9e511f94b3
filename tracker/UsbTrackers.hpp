// Finding Oculus Rift DK1/DK2 trackers on USB through libusb-1.0
// (vendor 0x2833, product 0x0001 DK1, 0x0021 DK2).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "OculusReport.hpp"

namespace arp::tracker {

constexpr uint16_t kOculusVendor = 0x2833, kDk1Product = 0x0001, kDk2Product = 0x0021;

struct UsbTrackerInfo {
  RiftModel model = RiftModel::DK1;
  int bus = 0, address = 0;
  bool can_open = false;     // false: permission denied or busy (see `problem`)
  std::string problem;
};

struct UsbScan {
  bool usb_available = false;  // libusb could be initialised and list devices
  std::string usb_error;       // why not, when it could not
  int devices_seen = 0;        // every USB device, trackers or not
  std::vector<UsbTrackerInfo> trackers;
};

UsbScan scan_usb_trackers();

}  // namespace arp::tracker
