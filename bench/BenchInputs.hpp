// Inputs and peers the benches share: the head motion a benchmarked frame
// sees, and the STREAM "copy" kernel that measures the machine's memory
// bandwidth in the same run (bytes counted as STREAM does: read + write).
#pragma once
#include <cstdint>
#include <vector>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::bench {

// A head turning at 200 deg/s, sampled at 1 kHz, over the first 40 ms.
inline dp::OrientationStream turning_head() {
  std::vector<dp::OrientationSample> s;
  for (int i = 0; i <= 40; ++i) {
    const double t = i * 1e-3;
    s.push_back({static_cast<int64_t>(t * 1e12), dp::from_yaw_pitch_roll_deg(20.0 + 200.0 * t, 10.0, 5.0)});
  }
  return dp::OrientationStream(s, "benchmark");
}

// The STREAM arrays: far larger than any cache (512 MiB each).
constexpr size_t kStreamDoubles = size_t{64} << 20;

// a[i] = b[i] on `threads` threads; returns the bytes STREAM counts.
inline int64_t stream_copy(std::vector<double>& a, const std::vector<double>& b, int threads) {
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int64_t i = 0; i < static_cast<int64_t>(a.size()); ++i) a[static_cast<size_t>(i)] = b[static_cast<size_t>(i)];
  return static_cast<int64_t>(2 * a.size() * sizeof(double));
}

// What the functional model must at least move per display pixel: read its
// lens vector (3 x 4 bytes) and write its colour (4 bytes).
constexpr double kCompulsoryBytesPerPixel = 16.0;

}  // namespace arp::bench
