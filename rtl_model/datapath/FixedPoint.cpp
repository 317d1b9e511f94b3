#include "FixedPoint.hpp"

#include <cmath>

namespace arp::dp {

const EnumNames<Rounding>& rounding_names() {
  static const EnumNames<Rounding> n{{Rounding::Floor, "floor"}, {Rounding::HalfUp, "half_up"}, {Rounding::HalfEven, "half_even"}};
  return n;
}

int64_t quantise_real(double v, int frac, int bits) {
  const SignedRange r(bits);
  const double scaled = std::ldexp(v, frac);
  if (!(scaled == scaled)) return 0;  // NaN never reaches here from validated inputs
  if (scaled >= static_cast<double>(r.hi)) return r.hi;
  if (scaled <= static_cast<double>(r.lo)) return r.lo;
  return static_cast<int64_t>(std::nearbyint(scaled));  // default FE mode: half-even
}

}  // namespace arp::dp
