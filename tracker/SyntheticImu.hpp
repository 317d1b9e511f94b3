// Synthetic IMU readings from a pose trace, as a head-mounted IMU at the
// head's centre would give them: the gyroscope reads the head-frame angular
// velocity plus a constant bias and white noise; the accelerometer reads the
// specific force of gravity (+9.80665 m/s^2 along world up, in the head frame)
// plus white noise. Seeded, so every figure made from it is reproducible.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

struct ImuReading {
  int64_t time_ps = 0;
  glm::dvec3 gyro{0.0};   // rad/s, head frame
  glm::dvec3 accel{0.0};  // m/s^2, head frame
};

struct ImuNoise {
  glm::dvec3 gyro_bias{0.0};   // rad/s
  double gyro_noise = 0.0;     // rad/s, standard deviation per sample
  double accel_noise = 0.0;    // m/s^2, standard deviation per sample
  uint64_t seed = 1;
};

constexpr double kStandardGravity = 9.80665;

// Needs samples that carry angular velocity (as SyntheticMotion's do).
std::vector<ImuReading> synthesize_imu(const std::vector<PoseSample>& truth, const ImuNoise& noise);

// One reading for one truth sample, drawing from `rng` (seeded with noise.seed) in a fixed order:
// gyro x, y, z, then accel x, y, z. synthesize_imu is this over a trace; a stream of any length
// (an hour of samples) calls it sample by sample in constant memory.
ImuReading imu_reading(const PoseSample& truth, const ImuNoise& noise, std::mt19937_64& rng);

}  // namespace arp::tracker
