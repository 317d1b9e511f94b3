#include "Validity.hpp"

#include <algorithm>
#include <cmath>

namespace arp::host {

namespace {
// When the eye has moved x at the latest: walking at v, turning at turn.speed_m_s until turning has moved it
// turn.reach_m (after reach / speed) and no further.
double time_to_move(double x, double v, const EyeTurn& turn) {
  if (turn.speed_m_s > 0 && turn.reach_m > 0) {
    if (x <= (v + turn.speed_m_s) * (turn.reach_m / turn.speed_m_s)) return x / (v + turn.speed_m_s);
    return v > 0 ? (x - turn.reach_m) / v : kForever;
  }
  return v > 0 ? x / v : kForever;
}
}  // namespace

Validity validity(const ValidityInputs& in, double th, const EyeTurn& turn) {
  // Inside or touching the bound, the object is as near as it gets: use the
  // surface distance, at least a centimetre.
  const double d = std::max(in.distance_m - in.radius_m, 0.01);
  const double r = std::max(in.radius_m, 1e-6);
  Validity v{kForever, kForever, kForever};
  v.translational_s = time_to_move(d * std::sqrt(2.0 * (1.0 - std::cos(th))), in.relative_speed_m_s, turn);
  v.size_s = time_to_move(0.5 * th * (d * d + r * r) / r, in.relative_speed_m_s, turn);
  if (in.spin_rad_s > 0) v.animation_s = d * th / (r * in.spin_rad_s);
  return v;
}

}  // namespace arp::host
