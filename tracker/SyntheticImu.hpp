// Synthetic IMU readings from a pose trace, as a head-mounted IMU at the
// head's centre would give them: the gyroscope reads the head-frame angular
// velocity plus a constant bias and white noise; the accelerometer reads the
// specific force of gravity (+9.80665 m/s^2 along world up, in the head frame)
// plus white noise; the magnetometer reads the earth's field (world frame,
// gauss) in the head frame plus white noise, drawn from its own stream so the
// gyroscope's and accelerometer's draws are the same with or without it.
// Seeded, so every figure made from it is reproducible.
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
  glm::dvec3 mag{0.0};    // gauss, head frame
};

struct ImuNoise {
  glm::dvec3 gyro_bias{0.0};   // rad/s
  double gyro_noise = 0.0;     // rad/s, standard deviation per sample
  double accel_noise = 0.0;    // m/s^2, standard deviation per sample
  // The earth's field, world frame (x right, y up, -z ahead at the start): 0.22 gauss horizontal toward -z,
  // 0.42 gauss down (a mid-northern latitude, 62 deg inclination).
  glm::dvec3 mag_field{0.0, -0.42, -0.22};
  double mag_noise = 0.0;      // gauss, standard deviation per sample
  glm::dvec3 mag_hard_iron{0.0};  // gauss, head frame: the device's own field, added to every magnetometer reading
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
