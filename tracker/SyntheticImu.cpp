#include "SyntheticImu.hpp"

#include <random>
#include <stdexcept>

namespace arp::tracker {

ImuReading imu_reading(const PoseSample& p, const ImuNoise& n, std::mt19937_64& rng) {
  if (!p.has_angular_velocity) throw std::invalid_argument("synthesize_imu needs samples with angular velocity");
  std::normal_distribution<double> g(0.0, 1.0);
  ImuReading r;
  r.time_ps = p.time_ps;
  // One draw per statement: the order of a constructor's arguments is unspecified, and the figures must
  // not change between compilers.
  double d[6];
  for (double& x : d) x = g(rng);
  const glm::dvec3 gyro_noise(d[0], d[1], d[2]), accel_noise(d[3], d[4], d[5]);
  r.gyro = p.angular_velocity + n.gyro_bias + n.gyro_noise * gyro_noise;
  r.accel = glm::conjugate(p.orientation) * glm::dvec3(0.0, kStandardGravity, 0.0) + n.accel_noise * accel_noise;
  return r;
}

std::vector<ImuReading> synthesize_imu(const std::vector<PoseSample>& truth, const ImuNoise& n) {
  std::mt19937_64 rng(n.seed);
  std::vector<ImuReading> out;
  out.reserve(truth.size());
  for (const auto& p : truth) out.push_back(imu_reading(p, n, rng));
  return out;
}

}  // namespace arp::tracker
