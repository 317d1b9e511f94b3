#include "ReciprocalUnit.hpp"

#include <cmath>

namespace arp::dp {

std::vector<uint32_t> build_reciprocal_table(int index_bits, int recip_frac) {
  const size_t n = size_t{1} << index_bits;
  std::vector<uint32_t> t(n);
  for (size_t i = 0; i < n; ++i) {
    const double lo = 1.0 + static_cast<double>(i) / static_cast<double>(n);
    const double hi = 1.0 + static_cast<double>(i + 1) / static_cast<double>(n);
    const double mid = 0.5 * (1.0 / lo + 1.0 / hi);
    t[i] = static_cast<uint32_t>(std::nearbyint(std::ldexp(mid, recip_frac)));
  }
  return t;
}

}  // namespace arp::dp
