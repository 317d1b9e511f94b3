#include "VideoTiming.hpp"

namespace arp::dp {

namespace {
__extension__ typedef __int128 i128;  // hour-long runs overflow 64-bit cycles*1e12
constexpr int64_t kPsPerSecond = 1'000'000'000'000;

int64_t floor_div(i128 a, i128 b) {
  i128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return static_cast<int64_t>(q);
}
}  // namespace

VideoTiming::VideoTiming(const VideoTimingConfig& c)
    : c_(c), frame_cycles_(int64_t{c.h_total()} * c.v_total()) {}

double VideoTiming::refresh_hz() const {
  return static_cast<double>(c_.pixel_clock_hz) / static_cast<double>(frame_cycles_);
}

int64_t VideoTiming::cycles_to_ps(int64_t cycles) const {
  return floor_div(static_cast<i128>(cycles) * kPsPerSecond, c_.pixel_clock_hz);
}

int64_t VideoTiming::ps_to_cycle_floor(int64_t ps) const {
  // Largest n with cycles_to_ps(n) <= ps, i.e. floor(n*1e12/f) <= ps  <=>  n*1e12 < (ps+1)*f.
  const i128 num = (static_cast<i128>(ps) + 1) * c_.pixel_clock_hz;
  int64_t n = floor_div(num, kPsPerSecond);
  if (static_cast<i128>(n) * kPsPerSecond == num) --n;
  return n;
}

}  // namespace arp::dp
