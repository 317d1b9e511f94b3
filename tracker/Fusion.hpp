// Orientation fusion as in the open Rift drivers: integrate the gyroscope as
// a quaternion; when the head is still pull the tilt toward the measured
// gravity by a fixed fraction of the error per second, and learn the
// gyroscope bias from the still readings. Yaw has no absolute reference
// without the magnetometer: its drift is what a residual bias leaves
// (docs/tracker.md has the figures).
//
// Yaw from the magnetometer (optional, yaw_gain > 0; the vendor SDK's yaw
// correction): the field measured in the head frame, turned into the world
// frame by the fused orientation, has a horizontal direction; the first
// reading fixes it as the reference heading, and every later one pulls the
// yaw toward it by yaw_gain of the error per second. Readings whose strength
// differs from the reference's by more than mag_tolerance (a nearby magnet or
// steel) are not used. A constant yaw rate error w (a residual gyro bias
// about the vertical) then settles at w / yaw_gain instead of growing. Off by
// default: a magnetometer must be calibrated (hard-iron offsets) first, and
// an uncalibrated one pulls the yaw by an amount that depends on the
// orientation; with mag_calibrate the offset is learned as the head moves
// (MagCalibration) and the yaw corrected only once it is known.
//
// The bias model. To a gyroscope and an accelerometer, a steady slow turn
// about the vertical and a gyro bias look alike: both are a constant rate with
// gravity unchanged. So the bias is learned only while the rate averaged over
// `still_filter_s` is below `bias_still_rate` (a turn slower than that is
// taken in part for bias) and the reading itself below `tilt_still_rate` (the
// average lags a movement's start and reversal; the reading alone would be
// too noisy to gate at the bias band), only slowly (time constant
// `bias_time_constant`: a slow turn held for T seconds at rate w loses about
// w T^2 / (2 tau)), and bounded: its size never exceeds `max_bias`. A larger
// real bias is not learned (its drift stays).
#pragma once
#include "MagCalibration.hpp"
#include "PoseSample.hpp"

namespace arp::tracker {

struct FusionParams {
  double tilt_gain = 0.5;           // 1/s: fraction of the tilt error removed per second while still (0..1000)
  double tilt_still_rate = 0.1;     // rad/s: corrected rate below which gravity corrects the tilt (> 0)
  double bias_still_rate = 0.02;    // rad/s (1.15 deg/s): averaged corrected rate below which the bias is learned (> 0)
  double bias_time_constant = 120;  // s: low-pass time constant of the bias estimate while still (> 0)
  double max_bias = 0.02;           // rad/s: the largest bias learned (its norm is clamped) (>= 0)
  double still_filter_s = 0.05;     // s: time constant of the low-passed rate stillness is judged on (> 0)
  double gravity_tolerance = 0.3;   // m/s^2: | |a| - g | below which the accelerometer sees only gravity (> 0)
  bool correct_tilt = true;
  bool estimate_bias = true;
  double yaw_gain = 0.0;            // 1/s: fraction of the heading error removed per second (0: no magnetometer) (0..10)
  double mag_tolerance = 0.3;       // fraction: |field| this far from the reference's is a disturbance, not used (> 0)
  // Learn the magnetometer's hard-iron offset as the head moves (MagCalibration) and correct the yaw only
  // once it is known, from the readings with it removed. Off: the readings are taken as they come.
  bool mag_calibrate = false;
  MagCalibrationParams calibration;
};

class Fusion {
 public:
  explicit Fusion(const FusionParams& p = {}, const glm::dquat& start = glm::dquat(1, 0, 0, 0));
  // One IMU reading (head frame) after dt seconds.
  void update(const glm::dvec3& gyro_rad_s, const glm::dvec3& accel_m_s2, double dt);
  // The same with a magnetometer reading (head frame; only its direction and relative strength are used).
  void update(const glm::dvec3& gyro_rad_s, const glm::dvec3& accel_m_s2, const glm::dvec3& mag, double dt);
  // Magnetometer readings used for yaw, and refused as disturbances, so far.
  int64_t mag_used() const { return mag_used_; }
  int64_t mag_refused() const { return mag_refused_; }
  // The hard-iron calibration (learning only with FusionParams::mag_calibrate).
  const MagCalibration& calibration() const { return cal_; }
  const glm::dquat& orientation() const { return q_; }
  const glm::dvec3& bias() const { return bias_; }
  const glm::dvec3& rate() const { return rate_; }  // last bias-corrected angular velocity, head frame

 private:
  FusionParams p_;
  glm::dquat q_;
  glm::dvec3 bias_{0.0}, rate_{0.0};
  glm::dvec3 gyro_lp_{0.0};  // the raw gyro, low-passed over still_filter_s
  bool lp_started_ = false;
  glm::dvec3 heading_ref_{0.0};  // world-frame horizontal field direction (unit; zero: not yet taken)
  double field_ref_ = 0;         // its strength
  int64_t mag_used_ = 0, mag_refused_ = 0;
  MagCalibration cal_;
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
