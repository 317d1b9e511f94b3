// Synthetic head motion, sampled at a given rate: constant-rate rotation,
// sinusoidal head shake, pendulum, with optional seeded angular noise. Each
// sample carries its exact angular velocity. Deterministic for a seed.
#pragma once
#include <cstdint>
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

}  // namespace arp::tracker
