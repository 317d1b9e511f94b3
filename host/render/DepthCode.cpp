#include "DepthCode.hpp"

#include <cstring>
#include <limits>

#include "common/VectorClones.hpp"

namespace arp::host {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ln y for y >= 1 (or +inf, read as 2^1024): y = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s),
// s = (m - 1) / (m + 1), |s| <= 0.1716, by its series to s^17 (the next term is below 1e-15 of ln m).
// Branch-free: a loop of it vectorises.
inline double series_log(double y) {
  uint64_t b;
  std::memcpy(&b, &y, sizeof b);
  const uint64_t mb = (b & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
  double m;
  std::memcpy(&m, &mb, sizeof m);
  // (Selects of values, never of operations, so that the loop if-converts under -ftrapping-math.)
  const double high = m > 1.4142135623730951 ? 1.0 : 0.0;
  m *= 1.0 - 0.5 * high;  // halved, exactly, when above sqrt(2)
  const double e = static_cast<double>(static_cast<int32_t>(b >> 52) - 1023) + high;
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  const double p = 1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 * (1.0 / 11 + s2 * (1.0 / 13 + s2 * (1.0 / 15 + s2 / 17)))))));
  return e * 0.6931471805599453 + 2.0 * s * p;
}

}  // namespace

ARP_VECTOR_CLONES
void DepthCode::codes(const double* distance_m, uint32_t* out, size_t n) const {
  const double L = log_range(), M = max_code();
  // The series' error on ln y, up to ln(far / near) + 1 at most 1e-13 of it, scaled into code units.
  const bool series = M < 0x1p31 && M / L * 1e-13 * (L + 1.0) < kTieMargin * 1e-3;
  constexpr size_t kChunk = 256;
  bool tie[kChunk];
  for (size_t base = 0; base < n; base += kChunk) {
    const size_t m = std::min(kChunk, n - base);
    const double* d = distance_m + base;
    uint32_t* c = out + base;
    if (!series) {
      for (size_t k = 0; k < m; ++k) c[k] = d[k] == kInfinity ? max_code() : code(d[k], L);
      continue;
    }
    int ties = 0;
    for (size_t k = 0; k < m; ++k) {  // vectorises
      const double dk = d[k];
      const double t = series_log((dk > near_m ? dk : near_m) / near_m) / L;
      const double x = (t < 1.0 ? t : 1.0) * M;
      const double r = x + 0.5;
      const int32_t whole = static_cast<int32_t>(r);  // r in [0.5, 2^31): truncation is floor
      const double frac = r - whole;
      c[k] = static_cast<uint32_t>(whole);
      const bool near_tie = (frac < kTieMargin) | (frac > 1.0 - kTieMargin);
      tie[k] = near_tie;
      ties += near_tie;
    }
    if (ties)
      for (size_t k = 0; k < m; ++k)
        if (tie[k] && d[k] != kInfinity) c[k] = code(d[k], L);
  }
}

}  // namespace arp::host
