// The reproducible scenario behind the fusion drift figures: bursts of head
// shaking about a tilted axis (2 s at 150 deg/s peak) separated by 3 s of
// stillness, sampled at 1 kHz, read by an IMU with a constant gyro bias and
// white noise. Used by bench/TrackerDrift and tests/TrackerTest.
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

std::vector<PoseSample> drift_truth(double duration_s, double rate_hz = 1000.0);
ImuNoise drift_imu_noise(uint64_t seed = 7);

// Runs fusion over the scenario and compares with the truth at the end.
DriftResult run_drift(const FusionParams& params, double duration_s, uint64_t seed = 7);

}  // namespace arp::tracker
