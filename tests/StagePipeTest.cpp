// A stage's register pipe (rtl_model/stages/StagePipe.hpp) between two clocked
// FIFOs under random traffic: every pixel's latency, from the clock it was
// taken to the clock the next stage sees it, is logged here from the outside
// (the compute call and the valid strobe), and the pipe's statistics must be
// that log's count, least, most and mean, and its count of clocks a finished
// pixel waited for a full output FIFO.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "rtl_model/stages/ClockedFifo.hpp"
#include "rtl_model/stages/StagePipe.hpp"

namespace arp::stage {
namespace {

struct Logged {
  StageStats stats;
  std::vector<int64_t> latencies;  // in output order
  int64_t stalls = 0;              // clocks a finished pixel found the output FIFO full
};

constexpr uint32_t kFiller = 0xffffffffu;  // a token already in the output FIFO at the start

// `cycles` clocks: the producer offers the next pixel with probability p_in, the consumer
// takes one when `reads(clock, random draw)` says so; the pipe's token carries its number.
// `prefilled`: the output FIFO starts full of filler tokens.
template <class Reads>
Logged drive(int latency, int depth, double p_in, Reads&& reads, uint32_t seed, bool prefilled = false,
             int64_t cycles = 20000) {
  ClockedFifo<ColorToken> in("in", depth), out("out", depth);
  if (prefilled) {
    for (int i = 0; i < depth; ++i) {
      ColorToken t{};
      t.sample = kFiller;
      out.write(t, -1);
      out.update();
    }
  }
  StagePipe<ColorToken> pipe(latency);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<int64_t> taken, left;
  uint32_t next = 0, expect = 0;
  Logged r;
  for (int64_t c = 0; c < cycles; ++c) {
    if (u(rng) < p_in && in.can_write()) {
      ColorToken t{};
      t.sample = next++;
      in.write(t, c);
    }
    if (out.can_read() && reads(c, u(rng))) {
      if (out.front().sample != kFiller) {
        EXPECT_EQ(out.front().sample, expect) << "order at clock " << c;
        ++expect;
      }
      out.read(c);
    }
    const bool out_full = !out.can_write();  // at the edge: the consumer's read frees a place only at the next
    pipe.tick(c, in, out, [&](const ColorToken& t, ColorToken& o) {
      EXPECT_EQ(t.sample, taken.size());
      taken.push_back(c);
      o = t;
    });
    // The oldest pixel not yet out is finished once latency - 1 clocks have passed since it was taken
    // (this clock's, for one register): held up if the FIFO was full.
    const size_t oldest = left.size();
    if (oldest < taken.size() && taken[oldest] + latency - 1 <= c && out_full) ++r.stalls;
    if (pipe.valid_out) left.push_back(c);
    in.update();
    out.update();
  }
  for (size_t i = 0; i < left.size(); ++i) r.latencies.push_back(left[i] + 1 - taken[i]);
  r.stats = pipe.stats();
  return r;
}

void expect_stats_are_the_log(const Logged& r, int latency) {
  const auto& l = r.latencies;
  ASSERT_FALSE(l.empty());
  EXPECT_EQ(r.stats.latency_cycles, latency);
  EXPECT_EQ(r.stats.pixels, static_cast<int64_t>(l.size()));
  EXPECT_EQ(r.stats.min_cycles, *std::min_element(l.begin(), l.end()));
  EXPECT_EQ(r.stats.max_cycles, *std::max_element(l.begin(), l.end()));
  int64_t sum = 0;
  for (int64_t x : l) sum += x;
  EXPECT_EQ(r.stats.mean_cycles, static_cast<double>(sum) / static_cast<double>(l.size()));  // the same sum: exact
  for (int64_t x : l) EXPECT_GE(x, latency);
  EXPECT_EQ(r.stats.stalled_cycles, r.stalls);
}

// A consumer reading with probability p.
auto at_random(double p) {
  return [p](int64_t, double draw) { return draw < p; };
}

TEST(StagePipe, AStreamingPipeTakesExactlyItsLatency) {
  for (int latency : {1, 2, 4}) {
    const Logged r = drive(latency, 2, 1.0, at_random(1.0), 7);
    expect_stats_are_the_log(r, latency);
    EXPECT_EQ(r.stats.max_cycles, latency);
    EXPECT_EQ(r.stats.stalled_cycles, 0);
  }
}

TEST(StagePipe, StatisticsAreTheLoggedLatenciesUnderBackpressure) {
  uint32_t seed = 1;
  for (int latency : {1, 2, 3, 5})
    for (int depth : {1, 2, 4})
      for (double p_out : {0.3, 0.7, 0.95}) {
        SCOPED_TRACE(testing::Message() << "latency " << latency << " depth " << depth << " p_out " << p_out);
        const Logged r = drive(latency, depth, 0.8, at_random(p_out), seed++);
        expect_stats_are_the_log(r, latency);
        // The consumer's refusals reach the pipe: some pixels wait longer, some still take the latency.
        EXPECT_GT(r.stats.max_cycles, latency);
        EXPECT_EQ(r.stats.min_cycles, latency);
        EXPECT_GT(r.stats.stalled_cycles, 0);
      }
}

TEST(StagePipe, EveryPixelLateWhenTheOutputIsNeverFreeInTime) {
  // The output FIFO starts full and the consumer first reads at clock 10, then every third clock:
  // no pixel leaves the clock it finishes, so none takes just the latency.
  for (int latency : {1, 2, 5})
    for (int depth : {1, 3}) {
      SCOPED_TRACE(testing::Message() << "latency " << latency << " depth " << depth);
      const Logged r = drive(latency, depth, 1.0, [](int64_t c, double) { return c >= 10 && c % 3 == 1; }, 3, true);
      expect_stats_are_the_log(r, latency);
      EXPECT_GT(r.stats.min_cycles, latency);
      EXPECT_GT(r.stats.stalled_cycles, 0);
    }
}

TEST(StagePipe, AnEmptyPipeReportsNothing) {
  StagePipe<ColorToken> pipe(3);
  const StageStats s = pipe.stats();
  EXPECT_EQ(s.pixels, 0);
  EXPECT_EQ(s.min_cycles, 0);
  EXPECT_EQ(s.max_cycles, 0);
  EXPECT_EQ(s.mean_cycles, 0.0);
}

}  // namespace
}  // namespace arp::stage
