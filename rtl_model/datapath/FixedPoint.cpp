#include "FixedPoint.hpp"

#include <cmath>

namespace arp::dp {

std::string to_string(Rounding r) {
  switch (r) {
    case Rounding::Floor: return "floor";
    case Rounding::HalfUp: return "half_up";
    case Rounding::HalfEven: return "half_even";
  }
  return "?";
}

bool parse_rounding(const std::string& s, Rounding& out) {
  if (s == "floor") { out = Rounding::Floor; return true; }
  if (s == "half_up") { out = Rounding::HalfUp; return true; }
  if (s == "half_even") { out = Rounding::HalfEven; return true; }
  return false;
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
