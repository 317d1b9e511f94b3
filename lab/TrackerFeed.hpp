// The head tracker as every architecture of the latency laboratory sees it:
// the true head motion (a dense pose trace), sampled at the tracker's rate
// and delivered after its latency. A system computing at time t has the
// latest report sampled at or before t - latency, time-stamped with its
// sample time, and may predict it forward (constant angular velocity or
// constant angular acceleration, estimated from the last reports).
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "tracker/PoseSample.hpp"
#include "common/Parameter.hpp"

namespace arp::lab {

struct TrackerModel {
  double rate_hz = 1000.0;    // reports per second
  double latency_s = 0.001;   // sample -> available to the system
};

enum class Prediction { None, Velocity, Acceleration };
const EnumNames<Prediction>& prediction_names();  // none, velocity, acceleration
inline bool parse_prediction(const std::string& s, Prediction& out) { return enum_parse(prediction_names(), s, out); }
inline std::string to_string(Prediction p) { return enum_name(prediction_names(), p); }

class TrackerFeed {
 public:
  // truth: at least two samples, times strictly increasing, unit quaternions
  // (InputError naming `source` and the sample otherwise).
  TrackerFeed(std::vector<tracker::PoseSample> truth, const TrackerModel& model, const std::string& source);

  const TrackerModel& model() const { return m_; }
  int64_t truth_begin_ps() const { return truth_.front().time_ps; }
  int64_t truth_end_ps() const { return truth_.back().time_ps; }
  // The true head orientation at t (slerp between trace samples; held outside the trace).
  glm::dquat truth(int64_t t_ps) const;
  // The true head position at t (linear between samples; the origin when the motion has none).
  glm::dvec3 truth_position(int64_t t_ps) const;
  bool has_positions() const { return positions_; }
  // Sample time of the latest report available at t.
  int64_t report_sample_ps(int64_t t_ps) const;
  // The orientation a system computing at `compute_ps` uses for `target_ps`:
  // the latest report, predicted from its sample time to the target.
  glm::dquat orientation_for(int64_t compute_ps, int64_t target_ps, Prediction p) const;

 private:
  glm::dquat report(int64_t k) const;  // report k, sampled at k / rate
  // The truth's samples around t (strictly inside its span) and the fraction of the way from the first to the second.
  struct Bracket {
    const tracker::PoseSample& a;
    const tracker::PoseSample& b;
    double u;
  };
  Bracket bracket(int64_t t) const;
  int64_t sample_time(int64_t k) const;
  std::vector<tracker::PoseSample> truth_;
  bool positions_ = false;
  TrackerModel m_;
  int64_t period_ps_, latency_ps_;
};

}  // namespace arp::lab
