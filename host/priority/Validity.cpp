#include "Validity.hpp"

#include <algorithm>
#include <cmath>

namespace arp::host {

Validity validity(const ValidityInputs& in, double th) {
  // Inside or touching the bound, the object is as near as it gets: use the
  // surface distance, at least a centimetre.
  const double d = std::max(in.distance_m - in.radius_m, 0.01);
  const double r = std::max(in.radius_m, 1e-6);
  Validity v{kForever, kForever, kForever};
  if (in.relative_speed_m_s > 0) {
    v.translational_s = d * std::sqrt(2.0 * (1.0 - std::cos(th))) / in.relative_speed_m_s;
    v.size_s = 0.5 * th * (d * d + r * r) / r / in.relative_speed_m_s;
  }
  if (in.spin_rad_s > 0) v.animation_s = d * th / (r * in.spin_rad_s);
  return v;
}

}  // namespace arp::host
