// Time on a clock: exact integer picoseconds of every edge of a clock of any
// frequency (the pixel clock, the host and tracker clocks), the one place
// cycles become times and back.
#pragma once
#include <cstdint>

namespace arp::dp {

// clock_cycle_to_ps for a run of cycles without a 128-bit division each:
// steps exactly when asked for the next cycle, recomputes otherwise.
class ClockTimeCursor {
 public:
  explicit ClockTimeCursor(int64_t hz);
  int64_t ps(int64_t cycle) {
    if (cycle == cycle_ + 1) {
      cycle_ = cycle;
      ps_ += q_;
      rem_ += r_;
      if (rem_ >= hz_) {
        rem_ -= hz_;
        ++ps_;
      }
      return ps_;
    }
    if (cycle != cycle_) seek(cycle);
    return ps_;
  }

 private:
  void seek(int64_t cycle);
  int64_t hz_, q_, r_;  // 1e12 = q * hz + r
  int64_t cycle_, ps_ = 0, rem_ = 0;
};

// Exact clock edges of an arbitrary clock: cycle n starts at floor(n * 1e12 / hz) ps.
// Time is int64 picoseconds (about 106 days either side of zero): a cycle
// whose time does not fit is std::overflow_error, never a wrapped time.
int64_t clock_cycle_to_ps(int64_t cycle, int64_t hz);
// The first cycle that starts at or after ps.
int64_t clock_cycle_at_or_after(int64_t ps, int64_t hz);
// The last cycle that starts at or before ps.
int64_t clock_cycle_at_or_before(int64_t ps, int64_t hz);
// The last cycle whose start fits in the time range.
int64_t last_clock_cycle_in_range(int64_t hz);

}  // namespace arp::dp
