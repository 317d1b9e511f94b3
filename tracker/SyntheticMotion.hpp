// Synthetic head motion, sampled at a given rate: constant-rate rotation,
// sinusoidal head shake, pendulum, with optional seeded angular noise. Each
// sample carries its exact angular velocity. Deterministic for a seed.
#pragma once
#include <cstdint>
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
};

}  // namespace arp::tracker
