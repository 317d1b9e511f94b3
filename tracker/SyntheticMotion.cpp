#include "SyntheticMotion.hpp"

#include <sstream>

#include "common/InputError.hpp"

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include "common/Units.hpp"

namespace arp::tracker {

namespace {

// angle(t) and its derivative, in radians, about a unit axis.
using AngleFn = std::function<void(double t, double& angle, double& rate)>;

std::vector<PoseSample> generate(const glm::dvec3& axis_in, const AngleFn& fn, const SamplingSpec& s) {
  if (!(s.rate_hz > 0.0) || !std::isfinite(s.rate_hz)) throw std::invalid_argument("sample rate must be positive");
  if (!(s.duration_s >= 0.0) || !std::isfinite(s.duration_s)) throw std::invalid_argument("duration must be >= 0");
  if (!(glm::length(axis_in) > 0.0)) throw std::invalid_argument("rotation axis must be non-zero");
  const glm::dvec3 axis = glm::normalize(axis_in);
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const auto count = static_cast<int64_t>(std::floor(s.duration_s * s.rate_hz + 1e-9)) + 1;
  std::vector<PoseSample> out;
  out.reserve(static_cast<size_t>(count));
  for (int64_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) / s.rate_hz;
    double angle = 0.0, rate = 0.0;
    fn(t, angle, rate);
    glm::dquat q = s.start * glm::angleAxis(angle, axis);  // rotation about the head-frame axis
    if (s.noise_deg > 0.0) {
      glm::dvec3 a(noise(rng), noise(rng), noise(rng));
      if (glm::length(a) > 0.0) q = q * glm::angleAxis(glm::radians(s.noise_deg) * noise(rng), glm::normalize(a));
    }
    PoseSample p;
    p.time_ps = std::llround((s.start_s + t) * 1e12);
    p.orientation = glm::normalize(q);
    p.has_angular_velocity = true;
    p.angular_velocity = axis * rate;
    out.push_back(p);
  }
  return out;
}

}  // namespace

std::vector<PoseSample> constant_rotation(const glm::dvec3& axis, double deg_per_s, const SamplingSpec& s) {
  const double w = glm::radians(deg_per_s);
  return generate(axis, [w](double t, double& a, double& r) { a = w * t; r = w; }, s);
}

std::vector<PoseSample> head_shake(const glm::dvec3& axis, double peak_deg_per_s, double frequency_hz,
                                   const SamplingSpec& s) {
  if (!(frequency_hz > 0.0)) throw std::invalid_argument("head shake frequency must be positive");
  const double omega = 2.0 * kPi * frequency_hz;
  const double amp = glm::radians(peak_deg_per_s) / omega;
  return generate(axis, [amp, omega](double t, double& a, double& r) {
    a = amp * std::sin(omega * t);
    r = amp * omega * std::cos(omega * t);
  }, s);
}

std::vector<PoseSample> pendulum(const glm::dvec3& axis, double amplitude_deg, double period_s, const SamplingSpec& s) {
  if (!(period_s > 0.0)) throw std::invalid_argument("pendulum period must be positive");
  const double omega = 2.0 * kPi / period_s, amp = glm::radians(amplitude_deg);
  return generate(axis, [amp, omega](double t, double& a, double& r) {
    a = amp * std::cos(omega * t);
    r = -amp * omega * std::sin(omega * t);
  }, s);
}

namespace {
glm::dvec3 parse_axis(const std::string& s) {
  std::stringstream ss(s);
  glm::dvec3 v(0.0);
  char c1 = 0, c2 = 0;
  if (!(ss >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !ss.eof())
    throw InputError("--axis", "", "expected three comma-separated numbers x,y,z");
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || glm::length(v) == 0.0)
    throw InputError("--axis", "", "the rotation axis must be finite and non-zero");
  return v;
}
}  // namespace

std::vector<PoseSample> MotionSpec::make(double start_s, double seconds) const {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) throw InputError("--seconds", "", "must be a positive number");
  if (!(hz > 0.0) || !std::isfinite(hz)) throw InputError("--hz", "", "must be a positive number");
  if (seconds * hz > 1e8) throw InputError("--seconds", "", "more than 1e8 samples; lower --seconds or --hz");
  if (!(noise >= 0.0) || !std::isfinite(noise)) throw InputError("--noise", "", "must be >= 0 degrees");
  if (!std::isfinite(start_s) || std::abs(start_s) > 9e6) throw InputError("--start", "", "must be within +-9e6 s");
  SamplingSpec s;
  s.rate_hz = hz;
  s.duration_s = seconds;
  s.start_s = start_s;
  s.noise_deg = noise;
  s.seed = seed;
  const glm::dvec3 ax = parse_axis(axis);
  if (motion == "rotate") {
    if (!std::isfinite(rate)) throw InputError("--rate", "", "must be finite");
    return constant_rotation(ax, rate, s);
  }
  if (motion == "shake") {
    if (!(frequency > 0.0) || !std::isfinite(frequency)) throw InputError("--frequency", "", "must be positive");
    if (!std::isfinite(peak)) throw InputError("--peak", "", "must be finite");
    return head_shake(ax, peak, frequency, s);
  }
  if (!(period > 0.0) || !std::isfinite(period)) throw InputError("--period", "", "must be positive");
  if (!std::isfinite(amplitude)) throw InputError("--amplitude", "", "must be finite");
  return pendulum(ax, amplitude, period, s);
}

}  // namespace arp::tracker
