// Edits of a recorded head motion, for low-rate logs: dropping samples a
// logger repeated, and resampling to a steady rate by spherical linear
// interpolation (positions linearly). Times stay where they were; nothing is
// extrapolated past the last sample.
#pragma once
#include <cstddef>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

// Removes every sample whose orientation and position equal the previous
// kept one's exactly (the first of each run stays); returns how many went.
size_t drop_repeats(std::vector<PoseSample>& samples);

// Samples at first + k / hz for every k up to the last sample's time. Samples
// at the same time: the later one counts. hz must be positive and finite, and
// the result at most kMaxResampled samples (about 1 GB): std::invalid_argument otherwise.
constexpr double kMaxResampled = 1e7;
std::vector<PoseSample> resample(const std::vector<PoseSample>& samples, double hz);
// A rate a user asks for (--resample): outside 1 .. 10 000 Hz is an InputError naming the option.
void check_resample_rate(double hz);
// resample() at such a rate: too many samples or fewer than two are an InputError naming the option and why.
std::vector<PoseSample> resample_as_asked(const std::vector<PoseSample>& samples, double hz);

}  // namespace arp::tracker
