// How long an object's image stays right to within a threshold angle theta_t
// (Regan & Pose; Chow 2005 figure 3): the minimum of
// - translational: the user (and the object) moving sideways by
//   x = d sqrt(2 (1 - cos theta_t)) shifts an object at distance d by theta_t;
//   valid until the eye can have moved x (x / relative speed, with no turning);
// - size: walking toward an object of radius r at distance d changes its
//   angular radius atan(r/d) by theta_t/2 after moving (theta_t/2)(d^2 + r^2)/r;
// - animation: a spinning object's surface (radius r, omega rad/s) moves
//   r omega t, which at distance d subtends theta_t after d theta_t / (r omega).
// A component that cannot change (zero speed and no turn, no spin) is infinite.
// The eyes sit either side of the head's centre, so a turning head moves them
// too (EyeTurn): over a time T an eye moves at most v T + min(s T, reach),
// s its speed on the circle it turns on and reach that circle's diameter (the
// longest chord). The translational and size components are the times that
// displacement first reaches theirs.
#pragma once
#include <cmath>
#include <limits>

namespace arp::host {

struct ValidityInputs {
  double distance_m;          // eye to the object's bounding-sphere centre
  double radius_m;            // bounding sphere
  double relative_speed_m_s;  // user speed plus the object's own
  double spin_rad_s;          // |angular velocity| of its animation
};

// The eyes' motion from the head turning at its present angular speed.
struct EyeTurn {
  double speed_m_s = 0;  // |omega| x the eyes' distance from the head's centre
  double reach_m = 0;    // the most turning moves an eye: twice that distance
};
// Eyes half of ipd_m either side of the centre (ipd_m 0: one eye, at the centre) of a head turning at turn_rad_s.
inline EyeTurn eye_turn(double turn_rad_s, double ipd_m) { return {std::abs(turn_rad_s) * 0.5 * ipd_m, ipd_m}; }

struct Validity {
  double translational_s, size_s, animation_s;
  double period_s() const {
    double p = translational_s;
    if (size_s < p) p = size_s;
    if (animation_s < p) p = animation_s;
    return p;
  }
};

Validity validity(const ValidityInputs& in, double threshold_rad, const EyeTurn& turn = {});

constexpr double kForever = std::numeric_limits<double>::infinity();

}  // namespace arp::host
