#include "SyntheticMotion.hpp"

#include <sstream>

#include "common/InputError.hpp"
#include "common/PrintfText.hpp"

#include <cmath>
#include <functional>
#include <algorithm>
#include <random>
#include <stdexcept>
#include "common/Units.hpp"

namespace arp::tracker {

MotionGenerator::MotionGenerator(const glm::dvec3& axis, AngleFn angle, const SamplingSpec& s)
    : angle_(std::move(angle)), s_(s), rng_(s.seed) {
  if (!(s.rate_hz > 0.0) || !std::isfinite(s.rate_hz)) throw std::invalid_argument("sample rate must be positive");
  if (!(s.duration_s >= 0.0) || !std::isfinite(s.duration_s)) throw std::invalid_argument("duration must be >= 0");
  axis_ = unit_axis(axis);
  count_ = static_cast<int64_t>(std::floor(s.duration_s * s.rate_hz + 1e-9)) + 1;
}

PoseSample MotionGenerator::next() {
  const double t = static_cast<double>(next_++) / s_.rate_hz;
  double angle = 0.0, rate = 0.0;
  angle_(t, angle, rate);
  glm::dquat q = s_.start * glm::angleAxis(angle, axis_);  // rotation about the head-frame axis
  if (s_.noise_deg > 0.0) {
    glm::dvec3 a(noise_(rng_), noise_(rng_), noise_(rng_));
    if (glm::length(a) > 0.0) q = q * glm::angleAxis(glm::radians(s_.noise_deg) * noise_(rng_), glm::normalize(a));
  }
  PoseSample p;
  p.time_ps = std::llround((s_.start_s + t) * 1e12);
  p.orientation = glm::normalize(q);
  p.has_angular_velocity = true;
  p.angular_velocity = axis_ * rate;
  return p;
}

void MotionGenerator::take_through(int64_t time_ps, std::vector<PoseSample>& out) {
  while (!done()) {
    out.push_back(next());
    if (out.back().time_ps > time_ps) return;
  }
}

namespace {

std::vector<PoseSample> generate(const glm::dvec3& axis, MotionGenerator::AngleFn fn, const SamplingSpec& s) {
  MotionGenerator g(axis, std::move(fn), s);
  std::vector<PoseSample> out;
  out.reserve(static_cast<size_t>(g.count()));
  while (!g.done()) out.push_back(g.next());
  return out;
}

MotionGenerator::AngleFn rotation_angle(double deg_per_s) {
  const double w = glm::radians(deg_per_s);
  return [w](double t, double& a, double& r) { a = w * t; r = w; };
}

MotionGenerator::AngleFn shake_angle(double peak_deg_per_s, double frequency_hz) {
  if (!(frequency_hz > 0.0)) throw std::invalid_argument("head shake frequency must be positive");
  const double omega = 2.0 * kPi * frequency_hz;
  const double amp = glm::radians(peak_deg_per_s) / omega;
  return [amp, omega](double t, double& a, double& r) {
    a = amp * std::sin(omega * t);
    r = amp * omega * std::cos(omega * t);
  };
}

MotionGenerator::AngleFn pendulum_angle(double amplitude_deg, double period_s) {
  if (!(period_s > 0.0)) throw std::invalid_argument("pendulum period must be positive");
  const double omega = 2.0 * kPi / period_s, amp = glm::radians(amplitude_deg);
  return [amp, omega](double t, double& a, double& r) {
    a = amp * std::cos(omega * t);
    r = -amp * omega * std::sin(omega * t);
  };
}

}  // namespace

std::vector<PoseSample> constant_rotation(const glm::dvec3& axis, double deg_per_s, const SamplingSpec& s) {
  return generate(axis, rotation_angle(deg_per_s), s);
}

std::vector<PoseSample> head_shake(const glm::dvec3& axis, double peak_deg_per_s, double frequency_hz,
                                   const SamplingSpec& s) {
  return generate(axis, shake_angle(peak_deg_per_s, frequency_hz), s);
}

std::vector<PoseSample> pendulum(const glm::dvec3& axis, double amplitude_deg, double period_s, const SamplingSpec& s) {
  return generate(axis, pendulum_angle(amplitude_deg, period_s), s);
}

glm::dvec3 unit_axis(const glm::dvec3& axis) {
  const double big = std::max({std::abs(axis.x), std::abs(axis.y), std::abs(axis.z)});
  if (!(big > 0.0) || !std::isfinite(big)) throw std::invalid_argument("rotation axis must be finite and non-zero");
  // An axis whose length is a normal number as it is: normalised directly, bit for bit as before (traces, plans'
  // motion hashes). Else scaled by its largest component first, so that neither 1e200 (whose length overflowed to
  // infinity, and the axis normalised to zero: a still head) nor 1e-320 (whose length underflowed) is lost.
  const double length = glm::length(axis);
  if (std::isnormal(length)) return glm::normalize(axis);
  return glm::normalize(axis / big);
}

glm::dvec3 parse_axis(const std::string& s) {
  std::stringstream ss(s);
  glm::dvec3 v(0.0);
  char c1 = 0, c2 = 0;
  if (!(ss >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !ss.eof())
    throw InputError("--axis", "", "expected three comma-separated numbers x,y,z");
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0))
    throw InputError("--axis", "", "the rotation axis must be finite and non-zero");
  return v;
}

std::vector<PoseSample> MotionSpec::make(double start_s, double seconds) const {
  MotionGenerator g = generator(start_s, seconds);
  std::vector<PoseSample> out;
  out.reserve(static_cast<size_t>(g.count()));
  while (!g.done()) out.push_back(g.next());
  return out;
}

namespace {
// The fastest synthetic turn: far past a head's few thousand degrees a second, short of where an angle's
// arithmetic over a run's hour loses its degrees.
constexpr double kMaxTurnDps = 1e6;
constexpr const char* kTurnLimit = "must be -1e6 .. 1e6 degrees per second";
}  // namespace

MotionGenerator MotionSpec::generator(double start_s, double seconds) const {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) throw InputError("--seconds", "", "must be a positive number");
  if (!(hz > 0.0) || !std::isfinite(hz)) throw InputError("--hz", "", "must be a positive number");
  if (hz < 1.0 || hz > kMaxSampleRateHz) throw InputError("--hz", printf_text("%g", hz), "must be 1 .. 1e6 Hz (a tracker's sample rate)");
  if (seconds * hz > 1e8) throw InputError("--seconds", "", "more than 1e8 samples; lower --seconds or --hz");
  if (!(noise >= 0.0) || !std::isfinite(noise)) throw InputError("--noise", "", "must be >= 0 degrees");
  if (noise > 180.0) throw InputError("--noise", printf_text("%g", noise), "must be at most 180 degrees a sample");
  if (!std::isfinite(start_s) || std::abs(start_s) > kPoseTimeLimitS)
    throw InputError("--start", "", "must be within +-" + pose_time_limit_text());
  // Its last sample too (at start + seconds, rounded to the sample clock): a trace every reader accepts.
  if (start_s + seconds > kPoseTimeLimitS)
    throw InputError("--seconds", printf_text("%g", seconds),
                     "the motion would end at " + printf_text("%.3f", start_s + seconds) + " s, beyond the +-" + pose_time_limit_text() +
                         " a trace holds: start earlier or make it shorter");
  SamplingSpec s;
  s.rate_hz = hz;
  s.duration_s = seconds;
  s.start_s = start_s;
  s.noise_deg = noise;
  s.seed = seed;
  const glm::dvec3 ax = parse_axis(axis);
  if (motion == "rotate") {
    if (!(std::abs(rate) <= kMaxTurnDps)) throw InputError("--rate", printf_text("%g", rate), kTurnLimit);
    return MotionGenerator(ax, rotation_angle(rate), s);
  }
  if (motion == "shake") {
    if (!(frequency > 0.0) || !std::isfinite(frequency)) throw InputError("--frequency", "", "must be positive");
    if (frequency > hz / 2.0)
      throw InputError("--frequency", printf_text("%g", frequency),
                       "is above half the sample rate (--hz " + printf_text("%g", hz) +
                           "): the samples would alias it; raise --hz or lower --frequency");
    if (!(std::abs(peak) <= kMaxTurnDps)) throw InputError("--peak", printf_text("%g", peak), kTurnLimit);
    return MotionGenerator(ax, shake_angle(peak, frequency), s);
  }
  if (!(period > 0.0) || !std::isfinite(period)) throw InputError("--period", "", "must be positive");
  if (period < 2.0 / hz)  // (the shake's rule: a swing faster than half the sample rate aliases)
    throw InputError("--period", printf_text("%g", period),
                     "is shorter than two samples (--hz " + printf_text("%g", hz) +
                         "): the samples would alias the swing; raise --hz or lengthen --period");
  if (!(std::abs(amplitude) <= 360.0)) throw InputError("--amplitude", printf_text("%g", amplitude), "must be -360 .. 360 degrees");
  return MotionGenerator(ax, pendulum_angle(amplitude, period), s);
}

}  // namespace arp::tracker
