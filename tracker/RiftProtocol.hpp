// The Oculus Rift DK1/DK2 USB protocol beyond the input report: the HID
// feature reports that configure the IMU and keep it streaming (brief §5,
// layouts as in the open drivers), and the device side of the input report
// (used by the device emulator in the tests and the fuzz corpus).
//
// Feature reports go out as HID SET_REPORT control transfers
// (bmRequestType 0x21, bRequest 0x09, wValue 0x03 << 8 | report id,
// wIndex 0 = the IMU interface).
//   DK1 config, report 2:     [2] [command id u16] [flags u8] [packet interval u8] [keep-alive interval ms u16]
//   DK1 keep-alive, report 8: [8] [command id u16] [keep-alive interval ms u16]
//   DK2 keep-alive, 0x11:     [0x11] [command id u16] [flags u8 = 0x0b] [keep-alive interval ms u16]
// Config flags: 0x04 use the factory calibration, 0x08 auto-calibration.
// Without a keep-alive before the interval runs out the device stops streaming.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "OculusReport.hpp"

namespace arp::tracker {

constexpr uint8_t kDk1ConfigReport = 2, kDk1KeepAliveReport = 8, kDk2KeepAliveReport = 0x11;
constexpr uint8_t kConfigUseCalibration = 0x04, kConfigAutoCalibration = 0x08;
constexpr uint8_t kHidSetReport = 0x09, kHidRequestTypeOut = 0x21;
constexpr uint16_t kHidFeatureReport = 0x0300;

std::vector<uint8_t> dk1_config_report(uint16_t command_id, uint8_t flags, uint8_t packet_interval, uint16_t keep_alive_ms);
std::vector<uint8_t> keep_alive_report(RiftModel model, uint16_t command_id, uint16_t keep_alive_ms);

// The 64 bytes a DK1 or DK2 sends for `r` (sample values must fit 21 bits signed).
std::array<uint8_t, kRiftReportSize> encode_report(const ImuReport& r);

}  // namespace arp::tracker
