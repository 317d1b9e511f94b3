#include "TraceEdit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/InputError.hpp"

namespace arp::tracker {

size_t drop_repeats(std::vector<PoseSample>& v) {
  if (v.empty()) return 0;
  size_t kept = 1;
  for (size_t i = 1; i < v.size(); ++i) {
    const PoseSample& last = v[kept - 1];
    if (v[i].orientation == last.orientation && v[i].has_position == last.has_position && v[i].position == last.position)
      continue;
    v[kept++] = v[i];
  }
  const size_t dropped = v.size() - kept;
  v.resize(kept);
  return dropped;
}

std::vector<PoseSample> resample(const std::vector<PoseSample>& v, double hz) {
  if (!(hz > 0) || !std::isfinite(hz)) throw std::invalid_argument("resample: the rate must be positive and finite");
  std::vector<PoseSample> out;
  if (v.empty()) return out;
  const int64_t t0 = v.front().time_ps, t1 = v.back().time_ps;
  const double step_ps = 1e12 / hz;
  const double last_k = std::floor((static_cast<double>(t1) - static_cast<double>(t0)) / step_ps);
  if (last_k >= kMaxResampled) throw std::invalid_argument("resample: more than 10 million samples at this rate");
  out.reserve(static_cast<size_t>(last_k) + 1);
  size_t j = 0;  // v[j] <= t < v[j + 1]
  for (int64_t k = 0; k <= static_cast<int64_t>(last_k); ++k) {
    const double td = static_cast<double>(t0) + static_cast<double>(k) * step_ps;
    const int64_t t = static_cast<int64_t>(std::llround(td));
    while (j + 1 < v.size() && v[j + 1].time_ps <= t) ++j;
    PoseSample p = v[j];
    p.time_ps = t;
    p.has_angular_velocity = false;
    if (j + 1 < v.size() && v[j + 1].time_ps > v[j].time_ps) {
      const PoseSample& b = v[j + 1];
      // (in double: two samples within the accepted +-9e6 s can be more ps apart than int64_t holds)
      const double f = (static_cast<double>(t) - static_cast<double>(v[j].time_ps)) /
                       (static_cast<double>(b.time_ps) - static_cast<double>(v[j].time_ps));
      p.orientation = glm::normalize(glm::slerp(v[j].orientation, b.orientation, f));  // GLM's slerp goes the short way
      if (p.has_position && b.has_position) p.position = v[j].position + f * (b.position - v[j].position);
    }
    out.push_back(p);
  }
  return out;
}

void check_resample_rate(double hz) {
  if (!(hz >= 1 && hz <= 10000)) throw InputError("--resample", std::to_string(hz), "must be between 1 and 10000 Hz");
}

std::vector<PoseSample> resample_as_asked(const std::vector<PoseSample>& samples, double hz) {
  check_resample_rate(hz);
  const std::string rate = std::to_string(hz);
  const double span_s = (static_cast<double>(samples.back().time_ps) - static_cast<double>(samples.front().time_ps)) * 1e-12;
  if (span_s * hz >= kMaxResampled)
    throw InputError("--resample", rate,
                     "would make " + std::to_string(static_cast<int64_t>(span_s * hz)) + " samples of this " +
                         std::to_string(span_s) + " s dataset (at most 10 million; is the time unit right?)");
  std::vector<PoseSample> out = resample(samples, hz);
  if (out.size() < 2) throw InputError("--resample", rate, "leaves fewer than two samples: the dataset is shorter than one period");
  return out;
}

}  // namespace arp::tracker
