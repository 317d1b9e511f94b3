// Hard-iron calibration of a head tracker's magnetometer, learned as the
// head moves. A reading is the earth's field turned into the head frame plus
// a constant offset (the device's own magnetised parts: the hard iron), so
// the readings of a turning head lie on a sphere around the offset. A linear
// least-squares sphere fit, |m|^2 = 2 h.m + k (k = r^2 - |h|^2), finds it.
//
// Readings are kept only when their direction from the current centre
// differs from every kept one by more than `min_separation_deg`: a head held
// still for minutes adds nothing, and memory is bounded (`max_points`). The
// calibration is `ready` once at least `min_points` are kept, they spread in
// all three axes (the smallest eigenvalue of their covariance at least
// (`min_spread` x r)^2: a head turning about one axis only traces a circle,
// on which the offset along that axis cannot be told) and the fit's rms
// residual is within `max_residual` of the radius. Until then no offset is
// applied. Soft iron (a distorted sphere) is not modelled.
#pragma once
#include <cstddef>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

struct MagCalibrationParams {
  int min_points = 12;               // kept readings before a fit counts (>= 4)
  size_t max_points = 200;           // kept readings at most (>= min_points)
  double min_separation_deg = 10;    // a reading this close in direction to a kept one is not kept (> 0)
  double min_spread = 0.15;          // the kept readings' least standard deviation along any axis, x r (> 0)
  double max_residual = 0.05;        // rms of | |m - h| - r | over r for a fit to be trusted (> 0)
};

class MagCalibration {
 public:
  explicit MagCalibration(const MagCalibrationParams& p = {});
  // One raw reading (head frame, any unit); refits when it is kept.
  void add(const glm::dvec3& reading);
  bool ready() const { return ready_; }
  const glm::dvec3& offset() const { return offset_; }  // the hard iron (zero until ready)
  double radius() const { return radius_; }             // the earth's field strength seen
  double residual() const { return residual_; }         // of the last fit, fraction of the radius
  size_t points() const { return kept_.size(); }
  // The reading with the hard iron removed.
  glm::dvec3 corrected(const glm::dvec3& reading) const { return reading - offset_; }

 private:
  void fit();
  MagCalibrationParams p_;
  std::vector<glm::dvec3> kept_;
  bool ready_ = false;
  glm::dvec3 offset_{0.0};      // applied: the last fit that was trusted
  glm::dvec3 offset_fit_{0.0};  // the last fit (the centre new readings are judged from)
  double radius_ = 0, residual_ = 1;
};

}  // namespace arp::tracker
