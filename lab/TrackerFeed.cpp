#include "TrackerFeed.hpp"

#include <algorithm>
#include <cmath>

#include "common/InputError.hpp"
#include "tracker/Fusion.hpp"

namespace arp::lab {

const EnumNames<Prediction>& prediction_names() {
  static const EnumNames<Prediction> n{{Prediction::None, "none"}, {Prediction::Velocity, "velocity"}, {Prediction::Acceleration, "acceleration"}};
  return n;
}

TrackerFeed::TrackerFeed(std::vector<tracker::PoseSample> truth, const TrackerModel& model, const std::string& source)
    : truth_(std::move(truth)), m_(model) {
  if (!(model.rate_hz >= 1.0 && model.rate_hz <= tracker::kMaxSampleRateHz)) throw InputError(source, "tracker rate", "must be 1 .. 1e6 reports per second");
  if (!(model.latency_s >= 0.0 && model.latency_s <= 1.0)) throw InputError(source, "tracker latency", "must be 0 .. 1 s");
  if (truth_.size() < 2) throw InputError(source, "", "the head motion needs at least two samples");
  for (size_t i = 0; i < truth_.size(); ++i) {
    const auto& s = truth_[i];
    const double n = glm::length(s.orientation);
    if (!std::isfinite(n) || std::abs(n - 1.0) > 1e-3)
      throw InputError(source, "sample " + std::to_string(i), "the orientation is not a unit quaternion");
    if (i > 0 && s.time_ps <= truth_[i - 1].time_ps)
      throw InputError(source, "sample " + std::to_string(i), "times must increase strictly");
    truth_[i].orientation = glm::normalize(s.orientation);
  }
  positions_ = std::all_of(truth_.begin(), truth_.end(), [](const tracker::PoseSample& p) { return p.has_position; });
  period_ps_ = static_cast<int64_t>(std::llround(1e12 / model.rate_hz));
  latency_ps_ = static_cast<int64_t>(std::llround(model.latency_s * 1e12));
}

TrackerFeed::Bracket TrackerFeed::bracket(int64_t t) const {
  const auto it = std::upper_bound(truth_.begin(), truth_.end(), t,
                                   [](int64_t v, const tracker::PoseSample& s) { return v < s.time_ps; });
  const auto& b = *it;
  const auto& a = *(it - 1);
  return {a, b, static_cast<double>(t - a.time_ps) / static_cast<double>(b.time_ps - a.time_ps)};
}

glm::dquat TrackerFeed::truth(int64_t t) const {
  if (t <= truth_.front().time_ps) return truth_.front().orientation;
  if (t >= truth_.back().time_ps) return truth_.back().orientation;
  const Bracket k = bracket(t);
  return glm::slerp(k.a.orientation, k.b.orientation, k.u);
}

glm::dvec3 TrackerFeed::truth_position(int64_t t) const {
  if (!positions_) return glm::dvec3(0.0);
  if (t <= truth_.front().time_ps) return truth_.front().position;
  if (t >= truth_.back().time_ps) return truth_.back().position;
  const Bracket k = bracket(t);
  return k.a.position + (k.b.position - k.a.position) * k.u;
}

int64_t TrackerFeed::sample_time(int64_t k) const { return k * period_ps_; }

glm::dquat TrackerFeed::report(int64_t k) const { return truth(sample_time(k)); }

int64_t TrackerFeed::report_sample_ps(int64_t t) const {
  const int64_t s = t - latency_ps_;
  // floor division for negative times
  const int64_t k = s >= 0 ? s / period_ps_ : -((-s + period_ps_ - 1) / period_ps_);
  return sample_time(k);
}

glm::dquat TrackerFeed::orientation_for(int64_t compute_ps, int64_t target_ps, Prediction p) const {
  const int64_t s = report_sample_ps(compute_ps);
  const int64_t k = s / period_ps_ - (s < 0 && s % period_ps_ ? 1 : 0);
  const glm::dquat q = report(k);
  if (p == Prediction::None || target_ps <= s) return q;
  const double dt = static_cast<double>(period_ps_) * 1e-12, h = static_cast<double>(target_ps - s) * 1e-12;
  const glm::dvec3 w1 = tracker::rate_between(report(k - 1), q, dt);
  if (p == Prediction::Velocity) return tracker::predict(q, w1, h);
  // Constant acceleration: the mean rate over the horizon is w + a h / 2
  // (w estimated half a period back, so it is carried forward too).
  const glm::dvec3 w0 = tracker::rate_between(report(k - 2), report(k - 1), dt);
  const glm::dvec3 acc = (w1 - w0) / dt;
  return tracker::predict(q, w1 + acc * (0.5 * dt + 0.5 * h), h);
}

}  // namespace arp::lab
