// Synthetic head motion, sampled at a given rate: constant-rate rotation,
// sinusoidal head shake, pendulum, with optional seeded angular noise. Each
// sample carries its exact angular velocity. Deterministic for a seed.
#pragma once
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

struct SamplingSpec {
  double rate_hz = 1000.0;   // tracker sample rate
  double duration_s = 1.0;
  double start_s = 0.0;
  glm::dquat start{1.0, 0.0, 0.0, 0.0};  // orientation at angle zero
  double noise_deg = 0.0;    // standard deviation of a random extra rotation per sample
  uint64_t seed = 1;
};

// The samples one at a time, in order, without holding them: a run of any
// length takes them as its frames need them (flat memory). Sample i is at
// start_s + i / rate_hz; the noise comes from one seeded generator in sample
// order, so taking them in pieces gives exactly what taking them at once does.
class MotionGenerator {
 public:
  // angle(t) and its derivative, in radians, about the unit axis.
  using AngleFn = std::function<void(double t, double& angle, double& rate)>;
  // std::invalid_argument on a non-positive rate, a negative duration or a zero axis.
  MotionGenerator(const glm::dvec3& axis, AngleFn angle, const SamplingSpec& s);

  bool done() const { return next_ >= count_; }
  int64_t count() const { return count_; }
  PoseSample next();
  // Appends every sample up to and including the first one after `time_ps`
  // (so the sample following any time up to `time_ps` is always taken), or to the end.
  void take_through(int64_t time_ps, std::vector<PoseSample>& out);

 private:
  glm::dvec3 axis_;
  AngleFn angle_;
  SamplingSpec s_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_{0.0, 1.0};
  int64_t count_ = 0, next_ = 0;
};

// Rotation about a fixed head-frame axis at a constant rate (deg/s; any sign, 0 allowed).
std::vector<PoseSample> constant_rotation(const glm::dvec3& axis, double deg_per_s, const SamplingSpec& s);

// angle(t) = A sin(2 pi f t) about the axis, with A chosen so the peak angular
// velocity is peak_deg_per_s (real heads reach about 370 deg/s).
std::vector<PoseSample> head_shake(const glm::dvec3& axis, double peak_deg_per_s, double frequency_hz,
                                   const SamplingSpec& s);

// A pendulum swing: angle(t) = amplitude cos(2 pi t / period) about the axis.
std::vector<PoseSample> pendulum(const glm::dvec3& axis, double amplitude_deg, double period_s, const SamplingSpec& s);

// Synthetic head motion described as data (what `--motion` and its options
// say): which motion, its parameters, and the sampling.
// "x,y,z" (--axis) as a vector; InputError naming --axis unless three finite numbers, not all zero.
glm::dvec3 parse_axis(const std::string& s);
// The unit vector along a finite, non-zero axis however it is scaled (1e200,0,0 is 1,0,0: its length overflows,
// and glm::normalize gives zero); std::invalid_argument otherwise.
glm::dvec3 unit_axis(const glm::dvec3& axis);

struct MotionSpec {
  std::string motion;        // rotate, shake, pendulum; empty: none
  std::string axis = "0,1,0";  // head-frame axis, x,y,z
  double rate = 100.0;       // rotate: deg/s
  double peak = 200.0;       // shake: peak deg/s
  double frequency = 1.0;    // shake: Hz
  double amplitude = 30.0;   // pendulum: deg
  double period = 2.0;       // pendulum: s
  double hz = 1000.0;        // samples per second
  double noise = 0.0;        // deg, standard deviation per sample
  uint64_t seed = 1;
  bool given() const { return !motion.empty(); }
  // Samples over [start_s, start_s + seconds]; InputError naming the option (--rate, --hz, ...) on bad values.
  std::vector<PoseSample> make(double start_s, double seconds) const;
  // The same samples, one at a time.
  MotionGenerator generator(double start_s, double seconds) const;
};

}  // namespace arp::tracker
