#include "Fusion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "SyntheticImu.hpp"

namespace arp::tracker {

glm::dquat integrate(const glm::dquat& q, const glm::dvec3& w, double dt) {
  const double rate = glm::length(w);
  if (rate * dt < 1e-300) return q;
  return glm::normalize(q * glm::angleAxis(rate * dt, w / rate));  // head-frame rate: compose on the right
}

glm::dvec3 rate_between(const glm::dquat& a, const glm::dquat& b, double dt) {
  glm::dquat d = glm::conjugate(a) * b;
  if (d.w < 0) d = -d;  // the shorter way round
  const double s = glm::length(glm::dvec3(d.x, d.y, d.z));
  if (s < 1e-15) return glm::dvec3(0.0);
  return glm::dvec3(d.x, d.y, d.z) / s * (2.0 * std::atan2(s, d.w) / dt);
}

glm::dquat predict(const glm::dquat& q, const glm::dvec3& w, double horizon_s) {
  if (!(horizon_s >= 0.0) || !std::isfinite(horizon_s)) throw std::invalid_argument("prediction horizon must be >= 0");
  return integrate(q, w, horizon_s);
}

double angle_between_deg(const glm::dquat& a, const glm::dquat& b) {
  const double d = std::min(1.0, std::abs(glm::dot(glm::normalize(a), glm::normalize(b))));
  return glm::degrees(2.0 * std::acos(d));
}

Fusion::Fusion(const FusionParams& p, const glm::dquat& start) : p_(p), q_(glm::normalize(start)), cal_(p.calibration) {
  if (!(p.tilt_gain >= 0 && p.tilt_gain <= 1000) || !(p.tilt_still_rate > 0) || !(p.bias_still_rate > 0) ||
      !(p.bias_time_constant > 0) || !(p.max_bias >= 0) || !(p.still_filter_s > 0) || !(p.gravity_tolerance > 0) ||
      !(p.yaw_gain >= 0 && p.yaw_gain <= 10) || !(p.mag_tolerance > 0))
    throw std::invalid_argument("fusion parameters out of range (tracker/Fusion.hpp states each range)");
}

void Fusion::update(const glm::dvec3& gyro, const glm::dvec3& accel, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) return;  // a repeated or backward timestamp adds nothing
  rate_ = gyro - bias_;
  q_ = integrate(q_, rate_, dt);
  if (!lp_started_) {
    gyro_lp_ = gyro;
    lp_started_ = true;
  } else {
    gyro_lp_ += std::min(1.0, dt / p_.still_filter_s) * (gyro - gyro_lp_);
  }
  const double a = glm::length(accel);
  const bool gravity_only = std::abs(a - kStandardGravity) < p_.gravity_tolerance;
  if (!gravity_only) return;
  // Still below `rate`: slow on average (the low-passed rate) and now (the reading itself, below
  // tilt_still_rate: the average lags, and as a fast movement reverses it passes zero while the head
  // still turns).
  const double average = glm::length(gyro_lp_ - bias_), now = glm::length(rate_);
  auto still_below = [&](double rate) { return average < rate && now < p_.tilt_still_rate; };
  if (p_.estimate_bias && still_below(p_.bias_still_rate)) {
    const double k = std::min(1.0, dt / p_.bias_time_constant);
    // The true rate is about zero, the reading is the bias. The raw reading, not the low-passed one,
    // whose tail after a movement stops would be learned as bias (0.02 deg/s in the drift scenario).
    bias_ += k * (gyro - bias_);
    const double b = glm::length(bias_);
    if (b > p_.max_bias) bias_ *= p_.max_bias / b;
  }
  if (p_.correct_tilt && still_below(p_.tilt_still_rate)) {
    const glm::dvec3 up_measured = accel / a;
    const glm::dvec3 up_predicted = glm::conjugate(q_) * glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 axis = glm::cross(up_measured, up_predicted);
    const double s = glm::length(axis);
    if (s > 1e-12) {
      const double err = std::atan2(s, glm::dot(up_measured, up_predicted));
      q_ = glm::normalize(q_ * glm::angleAxis(std::min(1.0, p_.tilt_gain * dt) * err, axis / s));
    }
  }
}

void Fusion::update(const glm::dvec3& gyro, const glm::dvec3& accel, const glm::dvec3& raw_mag, double dt) {
  update(gyro, accel, dt);
  if (!(p_.yaw_gain > 0) || !(dt > 0.0) || !std::isfinite(dt)) return;
  if (p_.mag_calibrate) {
    cal_.add(raw_mag);
    if (!cal_.ready()) return;  // no heading from a magnetometer whose own field is not known yet
  }
  const glm::dvec3 mag = p_.mag_calibrate ? cal_.corrected(raw_mag) : raw_mag;
  const double strength = glm::length(mag);
  if (!(strength > 0) || !std::isfinite(strength)) return;
  const glm::dvec3 world = q_ * mag;
  glm::dvec3 h(world.x, 0.0, world.z);
  const double hl = glm::length(h);
  if (hl < 1e-3 * strength) return;  // a field (nearly) vertical has no heading
  h /= hl;
  if (field_ref_ == 0) {
    heading_ref_ = h;
    field_ref_ = strength;
    return;
  }
  if (std::abs(strength - field_ref_) > p_.mag_tolerance * field_ref_) {
    ++mag_refused_;
    return;
  }
  ++mag_used_;
  // The angle that turns the measured heading onto the reference, about world up.
  const double err = std::atan2(glm::cross(h, heading_ref_).y, glm::dot(h, heading_ref_));
  q_ = glm::normalize(glm::angleAxis(std::min(1.0, p_.yaw_gain * dt) * err, glm::dvec3(0.0, 1.0, 0.0)) * q_);
}

}  // namespace arp::tracker
