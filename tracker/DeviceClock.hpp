// Device time -> simulated time for a tracker whose reports carry a wrapping
// tick counter (DK1: 16 bits of 1 ms, wraps every 65.5 s; DK2: 32 bits of
// 1 us, every 71.6 min). The counter is unwrapped (a step of more than half
// the range counts as going backwards: flagged, time held); time is anchored
// at the first report's arrival and runs at the device's rate corrected by
// the skew estimated from arrivals (least squares of arrival time against
// device time, after at least min_skew_span_s of device time).
#pragma once
#include <cstdint>

namespace arp::tracker {

class DeviceClock {
 public:
  DeviceClock(int counter_bits, int64_t tick_ps, double min_skew_span_s = 10.0);

  struct Mapped {
    int64_t time_ps;   // simulated time of the sample
    bool wrapped;      // the counter wrapped since the last report
    bool backwards;    // the counter went back: the report's time is held at the last one
  };
  // counter: the report's timestamp field; arrival_ps: when it arrived on the simulated timeline.
  Mapped map(uint64_t counter, int64_t arrival_ps);

  // Estimated (host rate / device rate - 1), parts per million; 0 until enough span.
  double skew_ppm() const { return skew_ * 1e6; }
  int64_t unwrapped_ticks() const { return ticks_; }

 private:
  int bits_;
  uint64_t mask_;
  int64_t tick_ps_;
  double min_span_ps_;
  bool started_ = false;
  uint64_t last_counter_ = 0;
  int64_t ticks_ = 0;            // unwrapped device ticks since the first report
  int64_t anchor_ps_ = 0;        // arrival of the first report
  double skew_ = 0.0;
  // Running sums for the least-squares slope of arrival (ps) against device time (ps).
  double n_ = 0, sx_ = 0, sy_ = 0, sxx_ = 0, sxy_ = 0;
};

}  // namespace arp::tracker
