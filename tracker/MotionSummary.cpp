#include "MotionSummary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/Units.hpp"

namespace arp::tracker {

namespace {

// The angle of the rotation from a to b; atan2 keeps small angles exact (acos near 1 does not).
double angle_deg(const glm::dquat& a, const glm::dquat& b) {
  const glm::dquat d = glm::conjugate(a) * b;
  return rad_to_deg(2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)));
}

double tilt_deg(const glm::dquat& q) {
  const glm::dvec3 up = q * glm::dvec3(0, 1, 0);
  return rad_to_deg(std::acos(std::clamp(up.y / glm::length(up), -1.0, 1.0)));
}

double seconds(int64_t ps) { return static_cast<double>(ps) * 1e-12; }
// From a to b in seconds, in double: two sample times within the accepted +-9e6 s are up to 1.8e19 ps apart,
// more than int64_t holds (at that span a double's step is a few nanoseconds: enough for a summary).
double seconds_between(int64_t a_ps, int64_t b_ps) { return (static_cast<double>(b_ps) - static_cast<double>(a_ps)) * 1e-12; }

}  // namespace

MotionSummary summarize_motion(const std::vector<PoseSample>& v, const MotionPlausibility& lim) {
  MotionSummary s;
  s.samples = v.size();
  if (v.empty()) return s;
  s.span_s = seconds_between(v.front().time_ps, v.back().time_ps);
  std::vector<double> dts;
  dts.reserve(v.size());
  for (size_t i = 1; i < v.size(); ++i)
    if (v[i].time_ps > v[i - 1].time_ps) dts.push_back(seconds_between(v[i - 1].time_ps, v[i].time_ps));
  if (!dts.empty()) {
    std::vector<double> sorted = dts;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
    s.median_period_s = sorted[sorted.size() / 2];
  }
  std::vector<double> speeds;
  speeds.reserve(v.size());
  double tilted_since = -1;
  for (size_t i = 0; i < v.size(); ++i) {
    const double tilt = tilt_deg(v[i].orientation);
    s.max_tilt_deg = std::max(s.max_tilt_deg, tilt);
    const double t = seconds(v[i].time_ps);
    // A tilted stretch lasts until the first upright sample after it (or the trace's last sample).
    if (tilt > lim.max_tilt_deg) {
      if (tilted_since < 0) tilted_since = t;
      s.longest_tilt_s = std::max(s.longest_tilt_s, t - tilted_since);
    } else if (tilted_since >= 0) {
      s.longest_tilt_s = std::max(s.longest_tilt_s, t - tilted_since);
      tilted_since = -1;
    }
    if (i == 0) continue;
    if (v[i].orientation == v[i - 1].orientation) ++s.repeats;
    if (v[i].time_ps == v[i - 1].time_ps) {
      ++s.same_time;
      continue;
    }
    const double dt = seconds_between(v[i - 1].time_ps, v[i].time_ps);
    if (dt < lim.burst_fraction * s.median_period_s) ++s.bursts;
    if (dt > lim.gap_periods * s.median_period_s && dt > 0.02) {
      ++s.gaps;
      s.longest_gap_s = std::max(s.longest_gap_s, dt);
    }
    const double w = angle_deg(v[i].orientation, v[i - 1].orientation) / dt;
    speeds.push_back(w);
    if (w > lim.max_speed_dps) ++s.fast_steps;
    if (w > s.peak_speed_dps) {
      s.peak_speed_dps = w;
      s.peak_speed_at_s = t;
    }
  }
  if (!speeds.empty()) {
    const size_t k = std::min(speeds.size() - 1, static_cast<size_t>(std::ceil(0.99 * static_cast<double>(speeds.size()))) - 1);
    std::nth_element(speeds.begin(), speeds.begin() + static_cast<long>(k), speeds.end());
    s.p99_speed_dps = speeds[k];
  }
  return s;
}

std::vector<std::string> describe(const MotionSummary& s) {
  char a[320], b[240];
  const double pct = s.samples > 1 ? 100.0 * static_cast<double>(s.repeats) / static_cast<double>(s.samples - 1) : 0.0;
  std::snprintf(a, sizeof a,
                "%zu samples over %.3f s, %.1f Hz (median interval %.3f ms); %zu gaps (longest %.3f s), %zu bursts, "
                "%zu at the same time, %zu repeated (%.0f %%)",
                s.samples, s.span_s, s.rate_hz(), s.median_period_s * 1e3, s.gaps, s.longest_gap_s, s.bursts, s.same_time,
                s.repeats, pct);
  std::snprintf(b, sizeof b, "angular speed: peak %.0f deg/s (at %.3f s), p99 %.0f deg/s; tilt from upright up to %.1f deg",
                s.peak_speed_dps, s.peak_speed_at_s, s.p99_speed_dps, s.max_tilt_deg);
  return {a, b};
}

std::vector<std::string> motion_warnings(const MotionSummary& s, const MotionPlausibility& lim) {
  std::vector<std::string> w;
  char b[320];
  const double rate = s.rate_hz();
  if (rate > lim.max_rate_hz) {
    std::snprintf(b, sizeof b, "a rate of %.1f kHz is implausible for a head tracker: is the time unit right (--time-unit)?", rate / 1e3);
    w.push_back(b);
  } else if (rate > 0 && rate < lim.min_rate_hz) {
    std::snprintf(b, sizeof b, "a rate of %.3f Hz is implausibly slow for a head tracker: is the time unit right (--time-unit)?", rate);
    w.push_back(b);
  }
  if (s.fast_steps > 0) {
    std::snprintf(b, sizeof b,
                  "%zu steps faster than a human head turns (%.0f deg/s), the fastest %.0f deg/s at %.3f s: a start-up jump, "
                  "bursts of samples or a wrong time unit?",
                  s.fast_steps, lim.max_speed_dps, s.peak_speed_dps, s.peak_speed_at_s);
    w.push_back(b);
  }
  if (s.longest_tilt_s >= lim.tilt_held_s) {
    std::snprintf(b, sizeof b,
                  "the head is tilted more than %.0f deg from upright for %.1f s (up to %.1f deg): are the axes right (--axes)?",
                  lim.max_tilt_deg, s.longest_tilt_s, s.max_tilt_deg);
    w.push_back(b);
  }
  if (s.samples > 1 && static_cast<double>(s.repeats) > lim.repeat_fraction * static_cast<double>(s.samples - 1)) {
    std::snprintf(b, sizeof b,
                  "%zu of %zu samples repeat the one before: the logger ran faster than the tracker, and the repeats make the "
                  "head look still, then fast (--drop-repeats)",
                  s.repeats, s.samples);
    w.push_back(b);
  }
  return w;
}

}  // namespace arp::tracker
