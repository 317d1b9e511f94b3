#include "RiftProtocol.hpp"

#include <algorithm>
#include <stdexcept>

namespace arp::tracker {

namespace {

void put16(std::vector<uint8_t>& v, uint16_t x) {
  v.push_back(static_cast<uint8_t>(x & 0xff));
  v.push_back(static_cast<uint8_t>(x >> 8));
}

void put16(uint8_t* p, uint16_t x) {
  p[0] = static_cast<uint8_t>(x & 0xff);
  p[1] = static_cast<uint8_t>(x >> 8);
}

// Three signed 21-bit values into 8 bytes, big-endian, bits 63-43, 42-22, 21-1.
void pack21(uint8_t* p, const std::array<int32_t, 3>& v) {
  uint64_t bits = 0;
  for (int k = 0; k < 3; ++k) {
    if (v[static_cast<size_t>(k)] < -(1 << 20) || v[static_cast<size_t>(k)] >= (1 << 20))
      throw std::out_of_range("IMU value does not fit 21 bits");
    bits |= (static_cast<uint64_t>(static_cast<uint32_t>(v[static_cast<size_t>(k)])) & 0x1fffff) << (43 - 21 * k);
  }
  for (int i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(bits >> (56 - 8 * i));
}

}  // namespace

std::vector<uint8_t> dk1_config_report(uint16_t command_id, uint8_t flags, uint8_t packet_interval, uint16_t keep_alive_ms) {
  std::vector<uint8_t> v{kDk1ConfigReport};
  put16(v, command_id);
  v.push_back(flags);
  v.push_back(packet_interval);
  put16(v, keep_alive_ms);
  return v;
}

std::vector<uint8_t> keep_alive_report(RiftModel model, uint16_t command_id, uint16_t keep_alive_ms) {
  std::vector<uint8_t> v{model == RiftModel::DK1 ? kDk1KeepAliveReport : kDk2KeepAliveReport};
  put16(v, command_id);
  if (model == RiftModel::DK2) v.push_back(0x0b);
  put16(v, keep_alive_ms);
  return v;
}

std::array<uint8_t, kRiftReportSize> encode_report(const ImuReport& r) {
  std::array<uint8_t, kRiftReportSize> b{};
  const bool dk1 = r.model == RiftModel::DK1;
  if (r.sample_count < 0 || r.sample_count > max_samples_held(r.model)) throw std::out_of_range("sample count");
  if (r.reported_sample_count > 255) throw std::out_of_range("reported sample count");
  // The count byte: what the device took, which may exceed what the report holds.
  const auto count = static_cast<uint8_t>(std::max(r.sample_count, r.reported_sample_count));
  size_t sample_at, mag_at;
  if (dk1) {
    b[0] = kDk1ReportId;
    b[1] = count;
    put16(&b[2], static_cast<uint16_t>(r.timestamp));
    put16(&b[4], r.last_command_id);
    put16(&b[6], static_cast<uint16_t>(r.temperature));
    sample_at = 8;
    mag_at = 56;
  } else {
    b[0] = kDk2ReportId;
    put16(&b[1], r.last_command_id);
    b[3] = count;
    put16(&b[4], r.samples_since_start);
    put16(&b[6], static_cast<uint16_t>(r.temperature));
    for (int i = 0; i < 4; ++i) b[8 + static_cast<size_t>(i)] = static_cast<uint8_t>(r.timestamp >> (8 * i));
    sample_at = 12;
    mag_at = 44;
  }
  for (int s = 0; s < r.sample_count; ++s) {
    pack21(&b[sample_at + 16 * static_cast<size_t>(s)], r.samples[static_cast<size_t>(s)].accel);
    pack21(&b[sample_at + 16 * static_cast<size_t>(s) + 8], r.samples[static_cast<size_t>(s)].gyro);
  }
  for (int k = 0; k < 3; ++k) put16(&b[mag_at + 2 * static_cast<size_t>(k)], static_cast<uint16_t>(r.magnetometer[static_cast<size_t>(k)]));
  return b;
}

}  // namespace arp::tracker
