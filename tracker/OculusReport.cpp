#include "OculusReport.hpp"

#include <algorithm>

namespace arp::tracker {

namespace {
uint16_t u16le(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
int16_t s16le(const uint8_t* p) { return static_cast<int16_t>(u16le(p)); }
uint32_t u32le(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}
int32_t sign21(uint64_t bits) {
  // Put the 21 bits at the top of a 32-bit word, then shift back arithmetically.
  return static_cast<int32_t>(static_cast<uint32_t>(bits & 0x1FFFFF) << 11) >> 11;
}
}  // namespace

std::array<int32_t, 3> unpack_21bit_triplet(const uint8_t* b) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | b[i];
  return {sign21(v >> 43), sign21(v >> 22), sign21(v >> 1)};
}

const char* to_string(ReportFault f) {
  switch (f) {
    case ReportFault::None: return "none";
    case ReportFault::Empty: return "empty";
    case ReportFault::WrongId: return "wrong report id";
    case ReportFault::TooShort: return "too short";
  }
  return "?";
}

bool decode_report(RiftModel model, const uint8_t* data, size_t length, ImuReport& out, std::string& error, ReportFault* fault) {
  const bool dk1 = model == RiftModel::DK1;
  const char* name = dk1 ? "DK1" : "DK2";
  const uint8_t id = dk1 ? kDk1ReportId : kDk2ReportId;
  auto refuse = [&](ReportFault f, std::string why) {
    if (fault) *fault = f;
    error = std::string(name) + " report: " + why;
    return false;
  };
  if (data == nullptr || length == 0) return refuse(ReportFault::Empty, "empty");
  if (data[0] != id) return refuse(ReportFault::WrongId, "id " + std::to_string(data[0]) + ", expected " + std::to_string(id));
  if (length < min_report_size(model))
    return refuse(ReportFault::TooShort, std::to_string(length) + " bytes, expected " + std::to_string(min_report_size(model)) +
                                             (dk1 ? " or more" : ""));
  if (fault) *fault = ReportFault::None;
  ImuReport r;
  r.model = model;
  r.reported_sample_count = dk1 ? data[1] : data[3];
  r.sample_count = std::min(r.reported_sample_count, max_samples_held(model));
  size_t sample_at, mag_at;
  if (dk1) {
    r.timestamp = u16le(data + 2);
    r.last_command_id = u16le(data + 4);
    r.temperature = s16le(data + 6);
    sample_at = 8;
    mag_at = 56;
  } else {
    r.last_command_id = u16le(data + 1);
    r.samples_since_start = u16le(data + 4);
    r.temperature = s16le(data + 6);
    r.timestamp = u32le(data + 8);
    sample_at = 12;
    mag_at = 44;
  }
  for (int s = 0; s < r.sample_count; ++s) {
    const uint8_t* p = data + sample_at + 16 * static_cast<size_t>(s);
    r.samples[static_cast<size_t>(s)].accel = unpack_21bit_triplet(p);
    r.samples[static_cast<size_t>(s)].gyro = unpack_21bit_triplet(p + 8);
  }
  for (int k = 0; k < 3; ++k) r.magnetometer[static_cast<size_t>(k)] = s16le(data + mag_at + 2 * static_cast<size_t>(k));
  out = r;
  return true;
}

}  // namespace arp::tracker
