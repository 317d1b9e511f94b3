#include "DeviceClock.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace arp::tracker {

DeviceClock::DeviceClock(int counter_bits, int64_t tick_ps, const DeviceClockLimits& limits)
    : mask_(counter_bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << counter_bits) - 1)),
      tick_ps_(tick_ps),
      limits_(limits) {
  if (counter_bits < 2 || counter_bits > 62) throw std::invalid_argument("counter width must be 2..62 bits");
  if (tick_ps <= 0) throw std::invalid_argument("tick must be positive");
  if (!(limits.min_skew_span_s > 0) || !(limits.stale_tolerance_s > 0) || !(limits.lead_tolerance_s > 0) || limits.max_held_reports < 1)
    throw std::invalid_argument("device clock limits: spans must be positive, max_held_reports at least 1");
}

int64_t DeviceClock::saturated(double ps) {
  constexpr double kMax = 9.2e18;  // inside int64_t's range
  return static_cast<int64_t>(std::llround(std::max(-kMax, std::min(kMax, ps))));
}

int64_t DeviceClock::time_of_ticks() const {
  const double device_ps = static_cast<double>(ticks_) * static_cast<double>(tick_ps_);
  return saturated(static_cast<double>(anchor_ps_) + offset_ + device_ps * (1.0 + skew_));
}

// Monotone chain: points come in increasing device time; a vertex on or above
// the segment from its predecessor to the new point is no longer on the hull.
void DeviceClock::add_to_hull(double x, double y) {
  while (hull_.size() >= 2) {
    const Point& a = hull_[hull_.size() - 2];
    const Point& b = hull_.back();
    if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) > 0) break;  // b strictly below a->new: keep it
    hull_.pop_back();
  }
  hull_.push_back({x, y});
  // Bounded: a segment of arrivals curving one way for hours cannot grow it; the oldest vertices say
  // least about the offset now.
  if (hull_.size() > kMaxHull) hull_.erase(hull_.begin(), hull_.begin() + static_cast<std::ptrdiff_t>(hull_.size() - kMaxHull / 2));
}

double DeviceClock::envelope_at_skew() const {
  double best = 0;
  bool any = false;
  for (const Point& p : hull_) {
    const double o = p.y - p.x * (1.0 + skew_);
    if (!any || o < best) best = o;
    any = true;
  }
  return best;
}

void DeviceClock::reanchor(int64_t arrival_ps) {
  anchor_ps_ = arrival_ps;
  ticks_ = 0;
  held_run_ = 0;
  n_ = sx_ = sy_ = sxx_ = sxy_ = 0;
  hull_.clear();
  offset_ = 0;
  ++reanchors_;
}

DeviceClock::Mapped DeviceClock::map(uint64_t counter, int64_t arrival_ps) {
  counter &= mask_;
  Mapped m{0, false, false, false, false, 0, 0};
  if (!started_) {
    started_ = true;
    anchor_ps_ = arrival_ps;
  } else {
    const uint64_t delta = (counter - last_counter_) & mask_;
    if (delta == 0 || delta > (mask_ >> 1)) {  // repeated or behind
      const uint64_t back = (last_counter_ - counter) & mask_;
      const bool restarted = static_cast<double>(back) * static_cast<double>(tick_ps_) > limits_.stale_tolerance_s * 1e12 ||
                             ++held_run_ >= limits_.max_held_reports;
      if (!restarted) {
        m.backwards = true;
        m.time_ps = last_time_ps_;
        m.device_ps = saturated(static_cast<double>(ticks_) * static_cast<double>(tick_ps_));
        return m;
      }
      m.jump_ps = saturated(-static_cast<double>(back) * static_cast<double>(tick_ps_));
      reanchor(arrival_ps);
      m.reanchored = true;
    } else {
      m.wrapped = counter < last_counter_;
      ticks_ += static_cast<int64_t>(delta);
      held_run_ = 0;
      const int64_t t = time_of_ticks();
      if (static_cast<double>(t - arrival_ps) > limits_.lead_tolerance_s * 1e12) {  // the device's time ran ahead of the host's
        m.jump_ps = t - arrival_ps;
        reanchor(arrival_ps);
        m.reanchored = true;
      }
    }
  }
  last_counter_ = counter;
  const double device_ps = static_cast<double>(ticks_) * static_cast<double>(tick_ps_);
  // Arrival against device time, relative to the anchor (doubles stay exact enough over days).
  const double y = static_cast<double>(arrival_ps - anchor_ps_);
  n_ += 1;
  sx_ += device_ps;
  sy_ += y;
  sxx_ += device_ps * device_ps;
  sxy_ += device_ps * y;
  const double var = sxx_ - sx_ * sx_ / n_;
  if (device_ps >= limits_.min_skew_span_s * 1e12 && var > 0) skew_ = (sxy_ - sx_ * sy_ / n_) / var - 1.0;
  add_to_hull(device_ps, y);
  offset_ = envelope_at_skew();
  // Monotonic: after a re-anchor to an arrival before the last time given (the device had led the
  // host), or the envelope moving earlier by more than a report's period, reports are held at the
  // last time until the timeline passes it.
  m.device_ps = saturated(device_ps);
  m.time_ps = time_of_ticks();
  if (given_ && m.time_ps <= last_time_ps_) {
    m.held = true;
    m.time_ps = last_time_ps_ + 1;  // 1 ps on: still monotonic, the report's samples are not lost
    last_time_ps_ = m.time_ps;
  } else {
    last_time_ps_ = m.time_ps;
    given_ = true;
  }
  return m;
}

}  // namespace arp::tracker
