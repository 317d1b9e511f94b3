#include "Validity.hpp"

#include <algorithm>
#include <cmath>

namespace arp::host {

namespace {
// When the eye has moved x at the latest: walking at v, turning at turn.speed_m_s until turning has moved it
// turn.reach_m (after reach / speed) and no further.
double time_to_move(double x, double v, const EyeTurn& turn) {
  const double s = turn.speed_m_s, reach = turn.reach_m;
  if (s > 0 && reach > 0) {
    if (s < kForever) {
      const double both = x / (v + s);  // turning and walking together, while turning has not moved it its reach
      if (s * both <= reach) return both;
    } else if (x <= reach) {
      return 0;  // an unbounded turn moves it its reach at once
    }
    return v > 0 ? (x - reach) / v : kForever;
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
