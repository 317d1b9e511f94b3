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

namespace {
// How many of a rising run's values are <= t. A run's photon times rise by about a pixel clock a pixel,
// so interpolation finds the place to within a pixel or two; the bisection is confined there once the
// place is confirmed, else it covers the run.
int64_t at_most(const int64_t* p, int64_t n, int64_t t) {
  if (t < p[0]) return 0;
  if (t >= p[n - 1]) return n;  // (also every run whose values are all equal)
  const int64_t g = (t - p[0]) * (n - 1) / (p[n - 1] - p[0]);
  const int64_t lo = std::max<int64_t>(0, g - 2), hi = std::min<int64_t>(n, g + 3);
  if (p[lo] <= t && (hi == n || p[hi] > t)) return std::upper_bound(p + lo, p + hi, t) - p;
  return std::upper_bound(p, p + n, t) - p;
}
}  // namespace

int64_t LatencyRuns::count_at_most(int64_t latency) const {
  int64_t c = 0;
  for (const Run& r : runs_) c += at_most(r.photon, r.n, r.sample + latency);
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
