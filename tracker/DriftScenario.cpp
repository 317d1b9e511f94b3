#include "DriftScenario.hpp"

#include <cmath>
#include "common/Units.hpp"

namespace arp::tracker {

std::vector<PoseSample> drift_truth(double duration_s, double rate_hz) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  const double omega = 2.0 * kPi * 1.0, amp = glm::radians(150.0) / omega;  // 1 Hz, 150 deg/s peak
  std::vector<PoseSample> out;
  const auto n = static_cast<int64_t>(duration_s * rate_hz) + 1;
  for (int64_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate_hz;
    const double phase = std::fmod(t, 5.0);  // 2 s shaking, 3 s still
    const bool moving = phase < 2.0;
    const double angle = moving ? amp * std::sin(omega * phase) : 0.0;
    const double rate = moving ? amp * omega * std::cos(omega * phase) : 0.0;
    PoseSample p;
    p.time_ps = std::llround(t * 1e12);
    p.orientation = glm::angleAxis(angle, axis);
    p.has_angular_velocity = true;
    p.angular_velocity = axis * rate;
    out.push_back(p);
  }
  return out;
}

ImuNoise drift_imu_noise(uint64_t seed) {
  ImuNoise n;
  n.gyro_bias = glm::radians(glm::dvec3(0.5, -0.3, 0.4));  // deg/s, a plausible MEMS gyro offset
  n.gyro_noise = 0.01;
  n.accel_noise = 0.05;
  n.seed = seed;
  return n;
}

DriftResult run_drift(const FusionParams& params, double duration_s, uint64_t seed) {
  const auto truth = drift_truth(duration_s);
  const ImuNoise noise = drift_imu_noise(seed);
  const auto imu = synthesize_imu(truth, noise);
  Fusion f(params, truth.front().orientation);
  for (size_t i = 1; i < imu.size(); ++i)
    f.update(imu[i].gyro, imu[i].accel, static_cast<double>(imu[i].time_ps - imu[i - 1].time_ps) * 1e-12);
  DriftResult r;
  const glm::dquat& est = f.orientation();
  const glm::dquat& tru = truth.back().orientation;
  r.total_deg = angle_between_deg(est, tru);
  const glm::dvec3 up_est = glm::conjugate(est) * glm::dvec3(0, 1, 0), up_true = glm::conjugate(tru) * glm::dvec3(0, 1, 0);
  r.tilt_deg = glm::degrees(std::acos(std::min(1.0, glm::dot(up_est, up_true))));
  r.bias_error_deg_s = glm::degrees(glm::length(f.bias() - noise.gyro_bias));
  return r;
}

}  // namespace arp::tracker
