#include "SyntheticMotion.hpp"

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

}  // namespace arp::tracker
