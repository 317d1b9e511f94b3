#include "DriftScenario.hpp"

#include <cmath>
#include "common/Units.hpp"

namespace arp::tracker {

PoseSample drift_truth_at(double t) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  const double omega = 2.0 * kPi * 1.0, amp = glm::radians(150.0) / omega;  // 1 Hz, 150 deg/s peak
  const double phase = std::fmod(t, 5.0);  // 2 s shaking, 3 s still
  const bool moving = phase < 2.0;
  const double angle = moving ? amp * std::sin(omega * phase) : 0.0;
  const double rate = moving ? amp * omega * std::cos(omega * phase) : 0.0;
  PoseSample p;
  p.time_ps = std::llround(t * 1e12);
  p.orientation = glm::angleAxis(angle, axis);
  p.has_angular_velocity = true;
  p.angular_velocity = axis * rate;
  return p;
}

std::vector<PoseSample> drift_truth(double duration_s, double rate_hz) {
  std::vector<PoseSample> out;
  const auto n = static_cast<int64_t>(duration_s * rate_hz) + 1;
  for (int64_t i = 0; i < n; ++i) out.push_back(drift_truth_at(static_cast<double>(i) / rate_hz));
  return out;
}

namespace {

// Fusion over a truth given sample by sample (1 kHz), the IMU read from it as it goes. Returns the
// fusion at the end and fills `last` with the last truth sample.
template <class Truth>
Fusion stream_fusion(const FusionParams& params, const ImuNoise& noise, double duration_s, Truth truth_at, PoseSample& last) {
  std::mt19937_64 rng(noise.seed);
  const auto n = static_cast<int64_t>(duration_s * 1000.0) + 1;
  PoseSample t0 = truth_at(0.0);
  ImuReading prev = imu_reading(t0, noise, rng);  // the first reading starts the clock
  Fusion f(params, t0.orientation);
  last = t0;
  for (int64_t i = 1; i < n; ++i) {
    last = truth_at(static_cast<double>(i) * 1e-3);
    const ImuReading r = imu_reading(last, noise, rng);
    const double dt = static_cast<double>(r.time_ps - prev.time_ps) * 1e-12;
    if (params.yaw_gain > 0)
      f.update(r.gyro, r.accel, r.mag, dt);
    else
      f.update(r.gyro, r.accel, dt);
    prev = r;
  }
  return f;
}

}  // namespace

ImuNoise drift_imu_noise(uint64_t seed) {
  ImuNoise n;
  n.gyro_bias = glm::radians(glm::dvec3(0.5, -0.3, 0.4));  // deg/s, a plausible MEMS gyro offset
  n.gyro_noise = 0.01;
  n.accel_noise = 0.05;
  n.mag_noise = 0.002;  // gauss: 0.4 % of the field, a few milligauss as MEMS magnetometers read
  n.seed = seed;
  return n;
}

DriftResult run_drift(const FusionParams& params, double duration_s, uint64_t seed) {
  const ImuNoise noise = drift_imu_noise(seed);
  PoseSample last;
  const Fusion f = stream_fusion(params, noise, duration_s, drift_truth_at, last);
  DriftResult r;
  const glm::dquat& est = f.orientation();
  const glm::dquat& tru = last.orientation;
  r.total_deg = angle_between_deg(est, tru);
  const glm::dvec3 up_est = glm::conjugate(est) * glm::dvec3(0, 1, 0), up_true = glm::conjugate(tru) * glm::dvec3(0, 1, 0);
  r.tilt_deg = glm::degrees(std::acos(std::min(1.0, glm::dot(up_est, up_true))));
  r.bias_error_deg_s = glm::degrees(glm::length(f.bias() - noise.gyro_bias));
  return r;
}

double run_slow_turn(const FusionParams& params, double deg_per_s, double seconds, uint64_t seed) {
  ImuNoise noise = drift_imu_noise(seed);
  noise.gyro_bias = glm::dvec3(0.0);
  const glm::dvec3 up(0, 1, 0);
  const double w = glm::radians(deg_per_s);
  auto turn = [&](double t) {
    PoseSample p;
    p.time_ps = std::llround(t * 1e12);
    p.orientation = glm::angleAxis(w * t, up);
    p.has_angular_velocity = true;
    p.angular_velocity = up * w;  // about the vertical, which stays the head's own y axis
    return p;
  };
  PoseSample last;
  const Fusion f = stream_fusion(params, noise, seconds, turn, last);
  return angle_between_deg(f.orientation(), last.orientation);
}

double run_bias_learning(const FusionParams& params, const glm::dvec3& bias, double seconds, uint64_t seed) {
  ImuNoise noise = drift_imu_noise(seed);
  noise.gyro_bias = bias;
  auto still = [](double t) {
    PoseSample p;
    p.time_ps = std::llround(t * 1e12);
    p.has_angular_velocity = true;
    return p;
  };
  PoseSample last;
  const Fusion f = stream_fusion(params, noise, seconds, still, last);
  return glm::length(f.bias() - bias) / glm::length(bias);
}

}  // namespace arp::tracker
