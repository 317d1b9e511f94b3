#include "CoreClock.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace arp::bench {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kLinksPerBlock = 1000;  // the .rept count below

#if defined(__x86_64__)
// Links of the chain per second over about `seconds`.
template <bool Multiply>
double links_per_second(double seconds) {
  uint64_t x = 3;
  const uint64_t one = 1;
  int64_t blocks = 0;
  const auto t0 = Clock::now();
  double s = 0;
  do {
    for (int i = 0; i < 256; ++i) {
      if constexpr (Multiply)
        asm volatile(".rept 1000\n\timul %0, %0\n\t.endr" : "+r"(x));
      else
        asm volatile(".rept 1000\n\tadd %1, %0\n\t.endr" : "+r"(x) : "r"(one));
    }
    blocks += 256;
    s = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (s < seconds);
  return static_cast<double>(blocks) * kLinksPerBlock / s;
}
#endif

}  // namespace

bool CoreClock::consistent(double tolerance) const {
  return add_hz > 0 && mul_hz > 0 && std::abs(add_hz - mul_hz) <= tolerance * std::max(add_hz, mul_hz);
}

std::optional<CoreClock> measure_core_clock(int trials, double seconds_per_trial) {
#if defined(__x86_64__)
  CoreClock best;
  for (int t = 0; t < std::max(trials, 1); ++t) {
    best.add_hz = std::max(best.add_hz, links_per_second<false>(seconds_per_trial));      // 1 cycle a link
    best.mul_hz = std::max(best.mul_hz, 3.0 * links_per_second<true>(seconds_per_trial));  // 3 cycles a link
  }
  return best;
#else
  (void)trials;
  (void)seconds_per_trial;
  return std::nullopt;
#endif
}

std::string describe(const std::optional<CoreClock>& c) {
  if (!c) return "core clock not measured (the calibration chains are x86-64 only)";
  char s[160];
  std::snprintf(s, sizeof s, "%.2f GHz (adds %.2f, multiplies %.2f%s)", c->hz() * 1e-9, c->add_hz * 1e-9,
                c->mul_hz * 1e-9, c->consistent() ? "" : ": THEY DISAGREE, no cycle figure");
  return s;
}

}  // namespace arp::bench
