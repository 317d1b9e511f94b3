#include "ReportDecoderFuzz.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tracker/OculusReport.hpp"
#include "tracker/RiftProtocol.hpp"

namespace arp::fuzz {

namespace {
[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "report decoder fuzz: %s\n", what);
  std::abort();
}
}  // namespace

int report_decoder_one_input(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const tracker::RiftModel model = (data[0] & 1) ? tracker::RiftModel::DK2 : tracker::RiftModel::DK1;
  // An exact-size heap copy, so AddressSanitizer catches any read past the end.
  std::vector<uint8_t> report(data + 1, data + size);
  tracker::ImuReport r;
  std::string error;
  const bool ok = tracker::decode_report(model, report.empty() ? nullptr : report.data(), report.size(), r, error);
  if (!ok) {
    if (error.empty()) fail("refused without a reason");
    return 0;
  }
  // A DK1 sends 62 or 64 bytes, a DK2 64 (the open drivers' sizes, not the decoder's constants).
  if (report.size() < (model == tracker::RiftModel::DK1 ? 62u : 64u)) fail("accepted a short report");
  if (r.sample_count < 0 || r.sample_count > (model == tracker::RiftModel::DK1 ? 3 : 2)) fail("sample count out of range");
  // Round trip: what was decoded encodes to the same fields.
  const auto again = tracker::encode_report(r);
  tracker::ImuReport r2;
  if (!tracker::decode_report(model, again.data(), again.size(), r2, error)) fail("re-encoded report refused");
  if (r2.sample_count != r.sample_count || r2.reported_sample_count != r.reported_sample_count || r2.timestamp != r.timestamp || r2.last_command_id != r.last_command_id ||
      r2.temperature != r.temperature || r2.magnetometer != r.magnetometer)
    fail("round trip changed a field");
  for (int s = 0; s < r.sample_count; ++s)
    if (r2.samples[static_cast<size_t>(s)].accel != r.samples[static_cast<size_t>(s)].accel ||
        r2.samples[static_cast<size_t>(s)].gyro != r.samples[static_cast<size_t>(s)].gyro)
      fail("round trip changed a sample");
  return 0;
}

}  // namespace arp::fuzz
