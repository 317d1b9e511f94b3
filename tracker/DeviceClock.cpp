#include "DeviceClock.hpp"

#include <cmath>
#include <stdexcept>

namespace arp::tracker {

DeviceClock::DeviceClock(int counter_bits, int64_t tick_ps, double min_skew_span_s)
    : bits_(counter_bits),
      mask_(counter_bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << counter_bits) - 1)),
      tick_ps_(tick_ps),
      min_span_ps_(min_skew_span_s * 1e12) {
  if (counter_bits < 2 || counter_bits > 62) throw std::invalid_argument("counter width must be 2..62 bits");
  if (tick_ps <= 0) throw std::invalid_argument("tick must be positive");
}

DeviceClock::Mapped DeviceClock::map(uint64_t counter, int64_t arrival_ps) {
  counter &= mask_;
  Mapped m{0, false, false};
  if (!started_) {
    started_ = true;
    anchor_ps_ = arrival_ps;
  } else {
    const uint64_t delta = (counter - last_counter_) & mask_;
    if (delta > (mask_ >> 1)) {  // more than half the range: it went back
      m.backwards = true;
    } else {
      m.wrapped = counter < last_counter_;
      ticks_ += static_cast<int64_t>(delta);
    }
  }
  if (!m.backwards) last_counter_ = counter;
  const double device_ps = static_cast<double>(ticks_) * static_cast<double>(tick_ps_);
  if (!m.backwards) {
    // Arrival against device time, relative to the anchor (doubles stay exact enough over days).
    const double y = static_cast<double>(arrival_ps - anchor_ps_);
    n_ += 1;
    sx_ += device_ps;
    sy_ += y;
    sxx_ += device_ps * device_ps;
    sxy_ += device_ps * y;
    const double var = sxx_ - sx_ * sx_ / n_;
    if (device_ps >= min_span_ps_ && var > 0) skew_ = (sxy_ - sx_ * sy_ / n_) / var - 1.0;
  }
  m.time_ps = anchor_ps_ + std::llround(device_ps * (1.0 + skew_));
  return m;
}

}  // namespace arp::tracker
