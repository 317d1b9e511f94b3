// Decoding the Oculus Rift DK1 and DK2 IMU input reports (USB HID, 64 bytes,
// 1000 Hz; layout as in the open drivers, brief §5). Reports are untrusted:
// the report id, every length and every count is checked, and a malformed
// report is rejected with a reason -- never read past its end.
//
// DK1, report id 1:  [1] samples, [2-3] timestamp ms (u16), [4-5] last
//   command id, [6-7] temperature (s16, 0.01 degC), 16-byte samples from [8]
//   (accel 8 bytes, gyro 8 bytes), magnetometer s16 at [56], [58], [60]. 62
//   bytes hold all of it; the device sends 62 or 64 (the vendor SDK and the
//   open drivers take both).
// DK2, report id 11: [1-2] last command id, [3] samples, [4-5] samples since
//   start, [6-7] temperature, [8-11] timestamp us (u32), samples from [12],
//   magnetometer s16 at [44], [46], [48]; 64 bytes.
// The sample count says how many samples the device took since its last
// report; the report holds at most 3 (DK1) or 2 (DK2) of them, the latest.
// A larger count is clamped, as the open drivers do (the rest were lost on
// the device), not refused.
// Multi-byte integers are little-endian, except the samples: each 8-byte
// block packs three signed 21-bit values big-endian (bits 63-43, 42-22, 21-1).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace arp::tracker {

enum class RiftModel : uint8_t { DK1, DK2 };

struct ImuSample {
  std::array<int32_t, 3> accel;  // 1e-4 m/s^2
  std::array<int32_t, 3> gyro;   // 1e-4 rad/s
};

struct ImuReport {
  RiftModel model = RiftModel::DK1;
  int sample_count = 0;           // samples held: the count clamped to what the report holds
  int reported_sample_count = 0;  // the count as sent (> sample_count: the device lost the difference)
  uint32_t timestamp = 0;        // DK1: ms (16-bit, wraps); DK2: us (32-bit, wraps)
  uint16_t last_command_id = 0;
  int16_t temperature = 0;       // 0.01 degC
  uint16_t samples_since_start = 0;  // DK2 only
  std::array<ImuSample, 3> samples{};
  std::array<int16_t, 3> magnetometer{};  // 1e-4 gauss
};

constexpr size_t kRiftReportSize = 64;     // the transfer buffer; what the DK2 sends
constexpr size_t kDk1MinReportSize = 62;  // what the DK1 may send
constexpr uint8_t kDk1ReportId = 1, kDk2ReportId = 11;
// The largest number of samples one report holds.
constexpr int max_samples_held(RiftModel m) { return m == RiftModel::DK1 ? 3 : 2; }
// The smallest report of the model that holds every field.
constexpr size_t min_report_size(RiftModel m) { return m == RiftModel::DK1 ? kDk1MinReportSize : kRiftReportSize; }

// Why a report was refused (counted per kind by the stream).
enum class ReportFault : uint8_t { None, Empty, WrongId, TooShort };
const char* to_string(ReportFault f);

// Three signed 21-bit values from 8 bytes (big-endian, bits 63-43, 42-22, 21-1).
std::array<int32_t, 3> unpack_21bit_triplet(const uint8_t* eight_bytes);

// Decodes one input report of the given model. On failure returns false and
// says why in `error` (the report id or length that is wrong) and, if given,
// in `fault`.
bool decode_report(RiftModel model, const uint8_t* data, size_t length, ImuReport& out, std::string& error,
                   ReportFault* fault = nullptr);

// SI units of the raw fields.
inline double accel_m_s2(int32_t raw) { return raw * 1e-4; }
inline double gyro_rad_s(int32_t raw) { return raw * 1e-4; }

}  // namespace arp::tracker
