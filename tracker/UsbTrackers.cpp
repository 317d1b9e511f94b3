#include "UsbTrackers.hpp"

#include <libusb.h>

namespace arp::tracker {

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
  for (ssize_t i = 0; i < n; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0 || d.idVendor != kOculusVendor) continue;
    if (d.idProduct != kDk1Product && d.idProduct != kDk2Product) continue;
    UsbTrackerInfo t;
    t.model = d.idProduct == kDk1Product ? RiftModel::DK1 : RiftModel::DK2;
    t.bus = libusb_get_bus_number(list[i]);
    t.address = libusb_get_device_address(list[i]);
    libusb_device_handle* h = nullptr;
    const int orc = libusb_open(list[i], &h);
    if (orc == 0) {
      t.can_open = true;
      libusb_close(h);
    } else if (orc == LIBUSB_ERROR_ACCESS) {
      t.problem = "permission denied: install scripts/udev/70-arpsim-oculus.rules (docs/tracker.md)";
    } else {
      t.problem = std::string("cannot open: ") + libusb_strerror(orc);
    }
    scan.trackers.push_back(t);
  }
  libusb_free_device_list(list, 1);
  libusb_exit(ctx);
  return scan;
}

}  // namespace arp::tracker
