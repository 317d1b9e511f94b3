#include "ClockTime.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "common/Units.hpp"

namespace arp::dp {

namespace {
__extension__ typedef __int128 i128;  // cycle * 1e12 overflows 64 bits after 106 days at 1 Hz... and 9 s at 1 GHz

[[noreturn]] void throw_out_of_range(int64_t cycle) {
  throw std::overflow_error("clock cycle " + std::to_string(cycle) + " is outside the 64-bit picosecond time range (about 106 days)");
}
}  // namespace

ClockTimeCursor::ClockTimeCursor(int64_t hz)
    : hz_(hz), q_(kPsPerSecond / hz), r_(kPsPerSecond % hz), cycle_(std::numeric_limits<int64_t>::min()) {}

void ClockTimeCursor::seek(int64_t cycle) {
  // floor(cycle * 1e12 / hz) and its remainder, for any sign.
  const i128 num = static_cast<i128>(cycle) * kPsPerSecond;
  i128 q = num / hz_, r = num % hz_;
  if (r < 0) {
    r += hz_;
    --q;
  }
  if (q > INT64_MAX || q < INT64_MIN) throw_out_of_range(cycle);
  cycle_ = cycle;
  ps_ = static_cast<int64_t>(q);
  rem_ = static_cast<int64_t>(r);
}

int64_t clock_cycle_to_ps(int64_t cycle, int64_t hz) {
  const i128 num = static_cast<i128>(cycle) * kPsPerSecond;
  i128 q = num / hz;
  if (num % hz < 0) --q;  // floor, also before time 0
  if (q > INT64_MAX || q < INT64_MIN) throw_out_of_range(cycle);
  return static_cast<int64_t>(q);
}

int64_t clock_cycle_at_or_after(int64_t ps, int64_t hz) {
  // Smallest n with floor(n * 1e12 / hz) >= ps  <=>  n * 1e12 >= ps * hz  <=>  n >= ceil(ps * hz / 1e12).
  const i128 num = static_cast<i128>(ps) * hz;
  i128 q = num / kPsPerSecond;
  if (num % kPsPerSecond > 0) ++q;  // ceil, for either sign
  return static_cast<int64_t>(q);
}

int64_t clock_cycle_at_or_before(int64_t ps, int64_t hz) {
  // Largest n with floor(n * 1e12 / hz) <= ps  <=>  n * 1e12 < (ps + 1) * hz.
  const i128 num = (static_cast<i128>(ps) + 1) * hz;
  i128 n = num / kPsPerSecond;
  if (num % kPsPerSecond < 0) --n;  // floor, also before time 0
  if (n * kPsPerSecond == num) --n;
  return static_cast<int64_t>(n);  // |n| <= (|ps| + 1) * hz / 1e12 + 1: fits for any clock up to 1 THz
}

int64_t last_clock_cycle_in_range(int64_t hz) { return static_cast<int64_t>(static_cast<i128>(INT64_MAX) * hz / kPsPerSecond); }

}  // namespace arp::dp
