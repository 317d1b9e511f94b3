// Orientation fusion as in the open Rift drivers: integrate the gyroscope as
// a quaternion; when the head is still (|accel| close to g and the corrected
// rate small) pull the tilt toward the measured gravity by a fixed fraction of
// the error per second, and learn the gyroscope bias by low-pass filtering
// the still readings. Yaw has no absolute reference without the magnetometer:
// its drift is what a residual bias leaves (docs/tracker.md has the figures).
#pragma once
#include "PoseSample.hpp"

namespace arp::tracker {

struct FusionParams {
  double tilt_gain = 0.5;          // fraction of the tilt error removed per second while still
  double bias_time_constant = 2.0; // s: low-pass time constant of the bias estimate while still
  double still_rate = 0.1;         // rad/s: corrected rate below which the head counts as still
  double gravity_tolerance = 0.3;  // m/s^2: | |a| - g | below which the accelerometer sees only gravity
  bool correct_tilt = true;
  bool estimate_bias = true;
};

class Fusion {
 public:
  explicit Fusion(const FusionParams& p = {}, const glm::dquat& start = glm::dquat(1, 0, 0, 0));
  // One IMU reading (head frame) after dt seconds.
  void update(const glm::dvec3& gyro_rad_s, const glm::dvec3& accel_m_s2, double dt);
  const glm::dquat& orientation() const { return q_; }
  const glm::dvec3& bias() const { return bias_; }
  const glm::dvec3& rate() const { return rate_; }  // last bias-corrected angular velocity, head frame

 private:
  FusionParams p_;
  glm::dquat q_;
  glm::dvec3 bias_{0.0}, rate_{0.0};
};

// Rotation of q by a head-frame angular velocity w held for dt seconds.
glm::dquat integrate(const glm::dquat& q, const glm::dvec3& w, double dt);

// The head-frame angular velocity taking orientation a to b in dt seconds
// (the inverse of integrate): how a rate is estimated from two reports.
glm::dvec3 rate_between(const glm::dquat& a, const glm::dquat& b, double dt);

// Constant-angular-velocity prediction: the pose `horizon_s` seconds after
// the sample, rotating on at its angular velocity (negative horizons refused).
glm::dquat predict(const glm::dquat& q, const glm::dvec3& w, double horizon_s);

// Angle between two orientations, degrees.
double angle_between_deg(const glm::dquat& a, const glm::dquat& b);

}  // namespace arp::tracker
