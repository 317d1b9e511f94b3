#include "LatencyRuns.hpp"

#include <algorithm>
#include <cstdint>

namespace arp::stage {

void LatencyRuns::reset() {
  runs_.clear();
  sorted_.clear();
  reset_ = pixels_ = 0;
}

void LatencyRuns::add_run(const int64_t* photon_ps, int n, int64_t sample_ps) {
  if (n <= 0) return;
  const int64_t* p = photon_ps;
  if (!std::is_sorted(p, p + n)) {
    sorted_.emplace_back(p, p + n);
    std::sort(sorted_.back().begin(), sorted_.back().end());
    p = sorted_.back().data();
  }
  // A pixel whose photon leaves before its sample was taken shows the register's reset value
  // (LatencyCollector::add): along a rising run, a prefix.
  const int64_t resets = std::lower_bound(p, p + n, sample_ps) - p;
  reset_ += resets;
  if (resets < n) {
    runs_.push_back({p + resets, n - resets, sample_ps});
    pixels_ += n - resets;
  }
}

int64_t LatencyRuns::count_at_most(int64_t latency) const {
  int64_t c = 0;
  for (const Run& r : runs_) c += std::upper_bound(r.photon, r.photon + r.n, r.sample + latency) - r.photon;
  return c;
}

void LatencyRuns::summarise(FrameReport& r) const {
  r.reset_pixels = reset_;
  if (pixels_ == 0) return;
  int64_t lo = INT64_MAX, hi = INT64_MIN;
  for (const Run& run : runs_) {
    lo = std::min(lo, run.photon[0] - run.sample);
    hi = std::max(hi, run.photon[run.n - 1] - run.sample);
  }
  r.latency_min_ps = lo;
  r.latency_max_ps = hi;
  // The element nth_element puts at pixels / 2: the least latency with more than pixels / 2 at or below it.
  const int64_t rank = pixels_ / 2 + 1;
  while (lo < hi) {
    const int64_t mid = lo + (hi - lo) / 2;
    if (count_at_most(mid) >= rank) hi = mid;
    else lo = mid + 1;
  }
  r.latency_median_ps = lo;
}

}  // namespace arp::stage
