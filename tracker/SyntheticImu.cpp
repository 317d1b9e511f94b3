#include "SyntheticImu.hpp"

#include <random>
#include <stdexcept>

namespace arp::tracker {

std::vector<ImuReading> synthesize_imu(const std::vector<PoseSample>& truth, const ImuNoise& n) {
  std::mt19937_64 rng(n.seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<ImuReading> out;
  out.reserve(truth.size());
  for (const auto& p : truth) {
    if (!p.has_angular_velocity) throw std::invalid_argument("synthesize_imu needs samples with angular velocity");
    ImuReading r;
    r.time_ps = p.time_ps;
    r.gyro = p.angular_velocity + n.gyro_bias + n.gyro_noise * glm::dvec3(g(rng), g(rng), g(rng));
    r.accel = glm::conjugate(p.orientation) * glm::dvec3(0.0, kStandardGravity, 0.0) +
              n.accel_noise * glm::dvec3(g(rng), g(rng), g(rng));
    out.push_back(r);
  }
  return out;
}

}  // namespace arp::tracker
