#include "OrientationMatrixUnit.hpp"

#include <stdexcept>

#include <algorithm>
#include <climits>
#include <cmath>

#include "PipelineSchedule.hpp"
#include "common/Units.hpp"
#include "common/InputError.hpp"

namespace arp::dp {

Quat normalised(const Quat& q, const std::string& source) {
  const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  if (!std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
    throw InputError(source, "quaternion", "has a NaN or infinite component");
  if (!(n2 > 1e-24) || !std::isfinite(n2))
    throw InputError(source, "quaternion", "has zero (or unrepresentable) length; a rotation needs a non-zero quaternion");
  const double inv = 1.0 / std::sqrt(n2);
  return {q.w * inv, q.x * inv, q.y * inv, q.z * inv};
}

static Quat mul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat from_yaw_pitch_roll_deg(double yaw, double pitch, double roll) {
  const double k = kPi / 360.0;  // half angle in radians per degree
  const Quat qy{std::cos(yaw * k), 0, std::sin(yaw * k), 0};
  const Quat qp{std::cos(pitch * k), std::sin(pitch * k), 0, 0};
  const Quat qr{std::cos(roll * k), 0, 0, std::sin(roll * k)};
  return mul(mul(qy, qp), qr);
}

bool rotate_fits_int32(const DatapathWidths& w, int64_t max_vec) {
  constexpr int64_t kMax = INT32_MAX;
  const RotateParams p(w);
  const int64_t max_m = int64_t{1} << (w.mat_frac + 1);  // the register's largest magnitude (mat_frac + 2 bits)
  // A shift of an int32_t by 32 or more is undefined: refused whatever the values (with Floor rounding no
  // bias catches it below; unreachable from a lens table, whose unit vectors keep the shift below 29).
  if (w.rot_frac + 2 > 32 || max_vec < 0 || max_m > kMax || p.shift.left > 30 || p.shift.right > 31) return false;
  if (max_vec > 0 && max_m > kMax / 3 / max_vec) return false;
  const int64_t sum = 3 * max_m * max_vec;  // the largest accumulator magnitude
  // Shifted left (an exact left shift) and rounded: the bias and the half-even bit on top.
  return sum <= ((kMax - p.shift.bias - 1) >> p.shift.left);
}

Mat3q quantise_rotation(const Quat& q, int mat_frac) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                       2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  Mat3q m{};
  for (int i = 0; i < 9; ++i) m.m[i] = static_cast<int32_t>(quantise_real(r[i], mat_frac, mat_frac + 2));
  return m;
}

OrientationStream::OrientationStream(std::vector<OrientationSample> samples, const std::string& source)
    : samples_(std::move(samples)) {
  if (samples_.empty()) throw InputError(source, "", "no orientation samples");
  for (size_t i = 0; i < samples_.size(); ++i) {
    const std::string place = "sample " + std::to_string(i);
    try {
      samples_[i].q = normalised(samples_[i].q, source);
    } catch (const InputError& e) {
      throw InputError(source, place, e.reason());
    }
    if (i > 0 && samples_[i].time_ps < samples_[i - 1].time_ps)
      throw InputError(source, place, "time " + std::to_string(samples_[i].time_ps) +
                                           " ps is earlier than the previous sample's");
  }
}

void OrientationStream::append(const std::vector<OrientationSample>& more, const std::string& source) {
  for (const OrientationSample& m : more) {
    const std::string place = "sample " + std::to_string(size());
    OrientationSample s = m;
    try {
      s.q = normalised(s.q, source);
    } catch (const InputError& e) {
      throw InputError(source, place, e.reason());
    }
    if (!samples_.empty() && s.time_ps < samples_.back().time_ps)
      throw InputError(source, place, "time " + std::to_string(s.time_ps) + " ps is earlier than the previous sample's");
    samples_.push_back(s);
  }
}

OrientationStream OrientationStream::constant(const Quat& q) {
  return OrientationStream({OrientationSample{0, q}}, "constant orientation");
}

size_t OrientationStream::index_at(int64_t t_ps) const {
  auto it = std::upper_bound(samples_.begin(), samples_.end(), t_ps,
                             [](int64_t t, const OrientationSample& s) { return t < s.time_ps; });
  if (it == samples_.begin()) {
    if (base_ > 0) throw std::logic_error("orientation stream read at " + std::to_string(t_ps) + " ps, before its window");
    return 0;
  }
  return base_ + static_cast<size_t>(it - samples_.begin()) - 1;
}

void OrientationStream::discard_before(int64_t t_ps) {
  auto it = std::upper_bound(samples_.begin(), samples_.end(), t_ps,
                             [](int64_t t, const OrientationSample& s) { return t < s.time_ps; });
  if (it == samples_.begin()) return;
  --it;  // the last sample at or before t_ps stays
  base_ += static_cast<size_t>(it - samples_.begin());
  samples_.erase(samples_.begin(), it);
}

size_t register_sample(const OrientationStream& s, const VideoTiming& t, int64_t cycle) {
  return s.index_at(t.cycles_to_ps(cycle));
}

LatchRule::LatchRule(const VideoTiming& t, LatchPolicy policy, int64_t lead_cycles)
    : timing_(t), policy_(policy), lead_(lead_cycles), fields_(t.config().fields_per_frame) {}

LatchRule::LatchRule(const ArpConfig& c) : LatchRule(VideoTiming(c.timing), c.pipeline.latch, PipelineSchedule(c).orientation_lead()) {}

int64_t LatchRule::read_cycle(int64_t frame, int eye, int x, int y) const {
  int64_t c = 0;
  switch (policy_) {
    case LatchPolicy::PerFrame: c = timing_.frame_start_cycle(frame); break;
    case LatchPolicy::PerField: c = timing_.field_start_cycle(frame, timing_.field_of_line(y)); break;
    case LatchPolicy::PerScanline: c = timing_.line_start_cycle(frame, y); break;
    case LatchPolicy::PerPixel: c = timing_.pixel_cycle(frame, eye, x, y); break;
  }
  return c - lead_;
}

}  // namespace arp::dp
