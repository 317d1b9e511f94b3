// The reproducible scenarios behind the fusion figures, each streamed sample
// by sample (constant memory: an hour is 3.6 million samples); the IMU has a
// magnetometer (drift_imu_noise: 2 milligauss of noise), which fusion uses when
// FusionParams::yaw_gain > 0:
// - drift: bursts of head shaking about a tilted axis (2 s at 150 deg/s peak)
//   separated by 3 s of stillness, sampled at 1 kHz, read by an IMU with a
//   constant gyro bias and white noise;
// - a slow turn: the head level, turning about the vertical at a constant
//   rate, read by an IMU with noise and no bias (what bias learning may eat);
// - bias learning: the head still, an IMU with a given bias and noise.
// Used by bench/TrackerDrift and tests/TrackerTest.
#pragma once
#include <vector>

#include "Fusion.hpp"
#include "SyntheticImu.hpp"

namespace arp::tracker {

struct DriftResult {
  double total_deg = 0.0;  // angle between fused and true orientation at the end
  double tilt_deg = 0.0;   // angle between the fused and true "up" at the end
  double bias_error_deg_s = 0.0;  // |estimated - true bias| at the end
};

PoseSample drift_truth_at(double t_s);
std::vector<PoseSample> drift_truth(double duration_s, double rate_hz = 1000.0);
ImuNoise drift_imu_noise(uint64_t seed = 7);

// Runs fusion over the drift scenario (1 kHz) and compares with the truth at the end.
DriftResult run_drift(const FusionParams& params, double duration_s, uint64_t seed = 7);

// Fusion over a level head turning about the vertical at deg_per_s for `seconds` (1 kHz, the drift
// scenario's noise, no bias): the error at the end, degrees.
double run_slow_turn(const FusionParams& params, double deg_per_s, double seconds, uint64_t seed = 7);

// Fusion over a still head read with gyro bias `bias_rad_s` (and the drift scenario's noise) for
// `seconds`: |estimated - true bias| / |true bias| at the end.
double run_bias_learning(const FusionParams& params, const glm::dvec3& bias_rad_s, double seconds, uint64_t seed = 7);

}  // namespace arp::tracker
