// The latency statistics of a frame made whole (the functional and verilated
// levels), as stage::LatencyCollector sums them up, without a partition over
// every pixel. A frame's pixels come in runs -- a line's pixels that latched
// the same orientation sample -- and along a run the photon times rise, so
// each run's latencies (photon - sample) are already sorted: the median is
// selected by value, counting each run by bisection. The same minimum,
// median, maximum and reset count as the collector over the same pixels
// (tested); a run whose photon times do not rise is sorted first.
#pragma once
#include <cstdint>
#include <vector>

#include "FrameReport.hpp"

namespace arp::stage {

class LatencyRuns {
 public:
  void reset();
  // `n` pixels with these photon times, all latching the sample taken at `sample_ps`. The photon
  // times must outlive summarise() (a frame's own array).
  void add_run(const int64_t* photon_ps, int n, int64_t sample_ps);
  void summarise(FrameReport& r) const;

 private:
  struct Run {
    const int64_t* photon;  // rising
    int64_t n, sample;
  };
  int64_t count_at_most(int64_t latency) const;  // latencies <= latency over every run
  std::vector<Run> runs_;
  std::vector<std::vector<int64_t>> sorted_;  // copies of the runs that did not rise
  int64_t reset_ = 0, pixels_ = 0;
};

}  // namespace arp::stage
