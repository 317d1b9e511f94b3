// The clock a core runs at, measured without hardware counters: this VM has
// none (perf stat: "cycles <not supported>"), and its nominal frequency
// (/proc/cpuinfo) is not what the core runs at under boost.
//
// A chain of dependent instructions of known latency runs one link per that
// many cycles whatever the clock, so links per second give the clock. Two
// chains are timed, 64-bit adds (latency 1) and 64-bit multiplies (latency 3
// on current x86-64 cores), and must agree: if a core ever shortened one of
// them (eliminated adds at rename, a faster multiplier) the two would differ
// and the figure is refused, not reported.
//
// Time stolen by the hypervisor or a neighbour only lowers a trial's clock, so
// the best trial is kept. A cycle count derived from it (wall seconds x Hz) is
// an upper bound when the work ran at a lower clock than the chain.
#pragma once

#include <optional>
#include <string>

namespace arp::bench {

struct CoreClock {
  double add_hz = 0;   // from the chain of adds
  double mul_hz = 0;   // from the chain of multiplies
  double hz() const { return add_hz; }
  // The two chains within this fraction of each other.
  bool consistent(double tolerance = 0.05) const;
};

// Best of `trials` of about `seconds_per_trial` each, on the calling thread.
// Empty where the chains are not implemented (not x86-64).
std::optional<CoreClock> measure_core_clock(int trials = 5, double seconds_per_trial = 0.02);

// "4.13 GHz (adds 4.13, multiplies 4.10)", or why there is no figure.
std::string describe(const std::optional<CoreClock>& c);

}  // namespace arp::bench
