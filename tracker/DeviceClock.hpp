// Device time -> simulated time for a tracker whose reports carry a wrapping
// tick counter (DK1: 16 bits of 1 ms, wraps every 65.5 s; DK2: 32 bits of
// 1 us, every 71.6 min).
//
// The model: the counter is unwrapped (a step of up to half its range is
// forward); time runs at the device's rate corrected by the skew estimated
// from arrivals (least squares of arrival time against device time, after at
// least min_skew_span_s of device time since the anchor), and is placed on
// the host's timeline by the *lower envelope* of the arrivals: a report can
// only arrive after the device sampled it (transfer latency, a busy host),
// never before, so the report that arrived soonest after its device time is
// the best measure of the offset. The segment's arrivals are kept as their
// lower convex hull (device time, arrival); the offset is the least of
// (arrival - device time x (1 + skew)) over its vertices. A report whose
// latency is the smallest yet moves the timeline earlier by the difference:
// the anchor report's own latency (20 ms if the host was busy when streaming
// started) is shed at the first report that arrived sooner, not carried for
// the whole session. So:
//   - a counter that repeats or steps back by at most `stale_tolerance_s` is
//     a stale or reordered report (a few transfers are in flight at once):
//     flagged `backwards`, its time held (the stream skips its samples);
//   - a counter that steps back by more, or that has not advanced for
//     `max_held_reports` reports in a row, means the device restarted;
//   - a counter that steps forward so that the device's time leads the
//     report's arrival by more than `lead_tolerance_s` jumped (a lead within
//     it is a late anchor, corrected by the envelope);
// and in the last two cases the clock re-anchors: a new segment starts at the
// report's arrival and carries on with the host's clock; the skew estimate is
// kept until the new segment has its own. The timeline stays monotonic: when
// a time would not be after the last one given (a re-anchor behind it, or the
// envelope moving earlier by more than a report's period), reports are
// `held`: each is given 1 ps after the last time until the timeline passes
// it. Their samples are kept (the stream fuses them over the device's own
// period), only their times are compressed, once, instead of a timeline
// ahead of the host for good.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace arp::tracker {

struct DeviceClockLimits {
  double min_skew_span_s = 10.0;   // device time before the skew is estimated, s (> 0)
  double stale_tolerance_s = 0.02; // a step back beyond this is a restart, s (> 0)
  double lead_tolerance_s = 0.25;  // device time leading arrival beyond this is a jump, s (> 0)
  int max_held_reports = 50;       // reports in a row without the counter advancing before re-anchoring (>= 1)
};

class DeviceClock {
 public:
  DeviceClock(int counter_bits, int64_t tick_ps, const DeviceClockLimits& limits = {});

  struct Mapped {
    int64_t time_ps;      // simulated time of the sample
    bool wrapped;         // the counter wrapped since the last report
    bool backwards;       // a stale report: its time is held at the last one
    bool reanchored;      // the device restarted or jumped: time carries on from the arrival
    bool held;            // its time would not be after the last one given (a re-anchor behind it, the envelope moving
                          // earlier by more than a report's period): 1 ps after it, until the timeline passes it
    int64_t jump_ps;      // when re-anchored: device time's step against the timeline's (negative: back)
    int64_t device_ps;    // the device's own time since the current anchor (unwrapped ticks x tick)
  };
  // counter: the report's timestamp field; arrival_ps: when it arrived on the simulated timeline.
  Mapped map(uint64_t counter, int64_t arrival_ps);

  // Estimated (host rate / device rate - 1), parts per million; 0 until enough span.
  double skew_ppm() const { return skew_ * 1e6; }
  // Unwrapped device ticks since the current anchor.
  int64_t unwrapped_ticks() const { return ticks_; }
  int64_t reanchors() const { return reanchors_; }
  // Where the current segment's times sit against its anchor's arrival, ps: the lower envelope (<= 0 while
  // the anchor is a hull vertex; trimming the hull past kMaxHull may drop it and move the timeline later,
  // by what the dropped vertices held down -- rare: jittered arrivals keep a few vertices).
  double envelope_offset_ps() const { return offset_; }
  // Vertices of the lower hull kept (a few for jittered arrivals; at most kMaxHull).
  size_t hull_size() const { return hull_.size(); }
  static constexpr size_t kMaxHull = 256;

 private:
  void reanchor(int64_t arrival_ps);
  int64_t time_of_ticks() const;
  static int64_t saturated(double ps);  // rounded, clamped inside int64_t's range

  uint64_t mask_;
  int64_t tick_ps_;
  DeviceClockLimits limits_;
  bool started_ = false;
  uint64_t last_counter_ = 0;
  int64_t ticks_ = 0;            // unwrapped device ticks since the anchor
  int64_t anchor_ps_ = 0;        // the anchor's arrival
  int64_t last_time_ps_ = 0;     // the last time given out
  bool given_ = false;           // ... once there is one
  int held_run_ = 0;             // reports in a row without the counter advancing
  int64_t reanchors_ = 0;
  double skew_ = 0.0;
  // Running sums for the least-squares slope of arrival (ps) against device time (ps), this segment.
  double n_ = 0, sx_ = 0, sy_ = 0, sxx_ = 0, sxy_ = 0;
  // Lower convex hull of (device time, arrival) of this segment, both relative to the anchor (ps), and
  // the offset it gives at the current skew.
  struct Point {
    double x, y;
  };
  std::vector<Point> hull_;
  double offset_ = 0;
  void add_to_hull(double x, double y);
  double envelope_at_skew() const;
};

}  // namespace arp::tracker
