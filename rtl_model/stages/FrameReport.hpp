// What every fidelity level reports for each scanned-out frame: underflows
// and the "orientation sample -> photon" latency of its pixels.
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "rtl_model/datapath/HmdFrame.hpp"

namespace arp::stage {

struct FrameReport {
  int64_t frame = 0;
  int64_t pixels = 0;           // pixel slots (per eye)
  int64_t underflows = 0;       // slots whose pixel was not ready: shown as the underflow colour
  int64_t late_discarded = 0;   // pixels that arrived after their slot and were dropped at scan-out
  int64_t reset_pixels = 0;     // pixels shown with the register's reset value (first sample later than the photon)
  int64_t latency_min_ps = 0, latency_median_ps = 0, latency_max_ps = 0;  // sample time -> photon
  int64_t first_photon_ps = 0, last_photon_ps = 0;
};

using FrameSink = std::function<void(const HmdFrame&, const FrameReport&)>;

// Collects each shown pixel's latency and sums a frame up.
class LatencyCollector {
 public:
  void reset() {
    lat_.clear();
    reset_ = 0;
  }
  // `pixels` pixels (the eyes of one slot) share this latency; it is kept
  // once -- the median over a list where every value appears equally often
  // is the same as over the list with each value once.
  void add(int64_t photon_ps, int64_t sample_ps, int pixels = 1) {
    if (sample_ps > photon_ps) reset_ += pixels;
    else lat_.push_back(photon_ps - sample_ps);
  }
  void summarise(FrameReport& r) {
    r.reset_pixels = reset_;
    if (lat_.empty()) return;
    const auto mid = lat_.begin() + static_cast<std::ptrdiff_t>(lat_.size() / 2);
    std::nth_element(lat_.begin(), mid, lat_.end());
    r.latency_median_ps = *mid;
    const auto mm = std::minmax_element(lat_.begin(), lat_.end());
    r.latency_min_ps = *mm.first;
    r.latency_max_ps = *mm.second;
  }

 private:
  std::vector<int64_t> lat_;
  int64_t reset_ = 0;
};

// The colour a slot shows when its pixel was not ready: full-scale magenta,
// which no correctly fetched pixel is guaranteed not to be, but which makes
// underflows visible in the images; the counts are the reliable record.
inline uint32_t underflow_color(int display_bits) {
  const uint32_t m = (1u << display_bits) - 1;
  return (m << (2 * display_bits)) | m;
}

}  // namespace arp::stage
