#include "SyntheticImu.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace arp::tracker {

namespace {

// A standard normal draw that is a function of (seed, time, axis) alone: the magnetometer's noise,
// kept out of the gyroscope's and accelerometer's stream (splitmix64, then Box-Muller).
double normal_at(uint64_t seed, int64_t time_ps, int axis) {
  auto mix = [](uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  const uint64_t a = mix(seed ^ mix(static_cast<uint64_t>(time_ps) * 4 + static_cast<uint64_t>(axis)));
  const uint64_t b = mix(a);
  const double u1 = (static_cast<double>(a >> 11) + 1.0) * 0x1.0p-53, u2 = static_cast<double>(b >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
}

}  // namespace

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
  r.mag = glm::conjugate(p.orientation) * n.mag_field + n.mag_hard_iron;
  if (n.mag_noise > 0)
    for (int a = 0; a < 3; ++a) r.mag[a] += n.mag_noise * normal_at(n.seed, p.time_ps, a);
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
