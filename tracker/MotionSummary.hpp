// What a recorded head motion looks like, told before it is used: its rate,
// its gaps, bursts and repeated samples, how fast the head turned and how far
// it tilted -- and warnings for what a human head does not do, which in a
// recorded dataset almost always means a wrong convention (time unit, axes)
// rather than a fast head. `tracker import` prints it; a run prints it for the
// trace's window before simulating.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

// Where "implausible for a human head" starts. Head turns peak at several
// hundred degrees per second (saccade-like head movements stay under ~1000 °/s).
struct MotionPlausibility {
  double max_speed_dps = 1500;    // faster than this between two samples: a warning
  double max_tilt_deg = 90;       // head up more than this from world up ...
  double tilt_held_s = 1.0;       // ... for this long: a warning (axes?)
  double max_rate_hz = 2000;      // a tracker faster than this: the time unit?
  double min_rate_hz = 5;         // slower than this: the time unit?
  double repeat_fraction = 0.2;   // more repeated samples than this: --drop-repeats
  double gap_periods = 5;         // an interval over this many median periods (and over 20 ms) is a gap
  double burst_fraction = 0.1;    // an interval under this fraction of the median period is a burst
};

struct MotionSummary {
  size_t samples = 0;
  double span_s = 0;
  double median_period_s = 0;
  size_t same_time = 0;           // intervals of zero
  size_t bursts = 0;              // intervals under burst_fraction of the median (and not zero)
  size_t gaps = 0;                // intervals over gap_periods medians and 20 ms
  double longest_gap_s = 0;
  size_t repeats = 0;             // samples whose orientation equals the previous one exactly
  double peak_speed_dps = 0, peak_speed_at_s = 0, p99_speed_dps = 0;
  size_t fast_steps = 0;          // steps over max_speed_dps
  double max_tilt_deg = 0;        // of the head's up from world up
  double longest_tilt_s = 0;      // longest stretch tilted over max_tilt_deg
  double rate_hz() const { return median_period_s > 0 ? 1.0 / median_period_s : 0.0; }
};

MotionSummary summarize_motion(const std::vector<PoseSample>& samples, const MotionPlausibility& limits = {});

// Two lines for a person: the rate and its irregularities, then speed and tilt.
std::vector<std::string> describe(const MotionSummary& s);
// One line per implausible property, each naming what to check; empty when none.
std::vector<std::string> motion_warnings(const MotionSummary& s, const MotionPlausibility& limits = {});

}  // namespace arp::tracker
