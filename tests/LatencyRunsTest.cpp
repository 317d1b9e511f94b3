// LatencyRuns (the functional level's frame latency statistics, selected by value over sorted runs)
// against LatencyCollector (every pixel's latency partitioned): the same report for the same pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "rtl_model/stages/LatencyRuns.hpp"

using namespace arp::stage;

namespace {

struct Line {
  std::vector<int64_t> photon;
  std::vector<std::pair<int, int64_t>> runs;  // (length, sample)
};

void expect_same(const std::vector<Line>& lines, const char* what) {
  LatencyCollector all;
  LatencyRuns runs;
  for (const Line& l : lines) {
    int x = 0;
    for (const auto& [n, sample] : l.runs) {
      for (int i = 0; i < n; ++i) all.add(l.photon[static_cast<size_t>(x + i)], sample);
      runs.add_run(l.photon.data() + x, n, sample);
      x += n;
    }
  }
  FrameReport a, b;
  all.summarise(a);
  runs.summarise(b);
  EXPECT_EQ(a.reset_pixels, b.reset_pixels) << what;
  EXPECT_EQ(a.latency_min_ps, b.latency_min_ps) << what;
  EXPECT_EQ(a.latency_median_ps, b.latency_median_ps) << what;
  EXPECT_EQ(a.latency_max_ps, b.latency_max_ps) << what;
}

}  // namespace

TEST(LatencyRuns, TheMedianMinimumMaximumAndResetsAreTheCollectors) {
  uint64_t state = 7;
  auto next = [&] { return state = state * 6364136223846793005ull + 1442695040888963407ull; };
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Line> lines(static_cast<size_t>(1 + next() % 12));
    const bool scrambled = trial % 4 == 3;  // photon times that do not rise along a line
    int64_t t = static_cast<int64_t>(next() % 1000000);
    for (Line& l : lines) {
      const int width = 1 + static_cast<int>(next() % 40);
      for (int x = 0; x < width; ++x) {
        t += static_cast<int64_t>(next() % 3);  // ties too
        l.photon.push_back(t);
      }
      if (scrambled) std::reverse(l.photon.begin() + width / 3, l.photon.end());
      for (int x = 0; x < width;) {
        const int n = std::min(width - x, 1 + static_cast<int>(next() % 9));
        // Samples before, inside and after the run's photons: latencies, zero latencies and resets.
        const int64_t sample = l.photon[static_cast<size_t>(x)] + static_cast<int64_t>(next() % 40) - 20;
        l.runs.push_back({n, sample});
        x += n;
      }
    }
    expect_same(lines, scrambled ? "scrambled" : "rising");
    if (HasFailure()) return;
  }
}

TEST(LatencyRuns, EveryPixelResetOrNoneGivesTheCollectorsReport) {
  std::vector<Line> resets{{{10, 11, 12}, {{3, 100}}}};  // every sample after its photon
  expect_same(resets, "all reset");
  std::vector<Line> one{{{50}, {{1, 20}}}};
  expect_same(one, "one pixel");
  std::vector<Line> even{{{1, 2, 3, 4}, {{4, 0}}}};  // an even count: the upper of the middle two, as nth_element
  expect_same(even, "even");
  expect_same({}, "empty");
}
