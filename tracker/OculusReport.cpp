#include "OculusReport.hpp"

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

bool decode_report(RiftModel model, const uint8_t* data, size_t length, ImuReport& out, std::string& error) {
  const bool dk1 = model == RiftModel::DK1;
  const char* name = dk1 ? "DK1" : "DK2";
  const uint8_t id = dk1 ? kDk1ReportId : kDk2ReportId;
  if (data == nullptr || length == 0) {
    error = std::string(name) + " report: empty";
    return false;
  }
  if (data[0] != id) {
    error = std::string(name) + " report: id " + std::to_string(data[0]) + ", expected " + std::to_string(id);
    return false;
  }
  if (length < kRiftReportSize) {
    error = std::string(name) + " report: " + std::to_string(length) + " bytes, expected " +
            std::to_string(kRiftReportSize);
    return false;
  }
  ImuReport r;
  r.model = model;
  const int max_samples = dk1 ? 3 : 2;
  r.sample_count = dk1 ? data[1] : data[3];
  if (r.sample_count > max_samples) {
    error = std::string(name) + " report: sample count " + std::to_string(r.sample_count) + " exceeds " +
            std::to_string(max_samples);
    return false;
  }
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
