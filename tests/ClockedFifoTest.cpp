// The clocked FIFO core (rtl_model/stages/ClockedFifo.hpp) that every cycle
// level's FIFOs share: its handshake and its occupancy statistics, against a
// cycle-by-cycle count kept here (not the core's own span accounting).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>

#include "rtl_model/stages/ClockedFifo.hpp"

using arp::stage::ClockedFifo;

namespace {

// What the statistics must say: each cycle's occupancy as seen during it, summed here.
struct Tally {
  int64_t cycles = 0, area = 0, full = 0, empty = 0, writes = 0, reads = 0;
  int max = 0;
  void see(int occupancy, int depth) {
    ++cycles;
    area += occupancy;
    full += occupancy == depth;
    empty += occupancy == 0;
    if (occupancy > max) max = occupancy;
  }
};

// Random pushes and pops on a FIFO of `depth`, some clocks skipped (a gated
// clock: nothing happens in them), with the probabilities given.
void random_traffic(int depth, double p_write, double p_read, uint32_t seed) {
  ClockedFifo<int> f("f", depth);
  f.start_statistics(0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Tally t;
  int next_value = 0, expect_front = 0;
  int64_t c = 0;
  const int64_t end = 20000;
  while (c < end) {
    if (u(rng) < 0.05) {  // a run of skipped clocks: the occupancy holds
      const int64_t skip = std::min<int64_t>(end - c, 1 + static_cast<int64_t>(u(rng) * 30));
      for (int64_t k = 0; k < skip; ++k) t.see(f.occupancy(), depth);
      c += skip;
      continue;
    }
    t.see(f.occupancy(), depth);
    ASSERT_EQ(f.can_write(), f.occupancy() < depth);
    ASSERT_EQ(f.can_read(), f.occupancy() > 0);
    if (f.can_read() && u(rng) < p_read) {
      ASSERT_EQ(f.front(), expect_front);  // in order, nothing lost
      ++expect_front;
      f.read(c);
      ++t.reads;
      EXPECT_FALSE(f.can_read());  // one read a clock
    }
    if (f.can_write() && u(rng) < p_write) {
      f.write(next_value++, c);
      ++t.writes;
      EXPECT_FALSE(f.can_write());  // one write a clock
    }
    f.update();
    ++c;
  }
  const auto s = f.stats(end);
  EXPECT_EQ(t.cycles, end);
  EXPECT_EQ(s.depth, depth);
  EXPECT_EQ(s.writes, t.writes);
  EXPECT_EQ(s.reads, t.reads);
  EXPECT_EQ(s.max_occupancy, t.max);
  EXPECT_EQ(s.full_cycles, t.full);
  EXPECT_EQ(s.empty_cycles, t.empty);
  EXPECT_DOUBLE_EQ(s.mean_occupancy, static_cast<double>(t.area) / static_cast<double>(end));
  EXPECT_GT(t.full, 0);  // the traffic reached both ends
  EXPECT_GT(t.empty, 0);
}

}  // namespace

TEST(ClockedFifo, StatisticsEqualACycleByCycleCountUnderRandomTraffic) {
  random_traffic(4, 0.6, 0.6, 1);  // streaming: many clocks read and write at once
  random_traffic(4, 0.8, 0.4, 2);  // mostly full
  random_traffic(3, 0.3, 0.9, 3);  // mostly empty
  random_traffic(1, 0.7, 0.7, 4);
}

TEST(ClockedFifo, AWriteIsSeenAndAReadFreesItsPlaceOnlyAtTheEdge) {
  ClockedFifo<int> f("f", 1);
  f.start_statistics(0);
  f.write(7, 0);
  EXPECT_FALSE(f.can_read());  // not before the edge
  EXPECT_THROW(f.write(8, 0), std::logic_error);
  f.update();
  ASSERT_TRUE(f.can_read());
  EXPECT_EQ(f.front(), 7);
  EXPECT_FALSE(f.can_write());  // full: a read this clock frees the place only at the edge
  f.read(1);
  EXPECT_THROW(f.write(9, 1), std::logic_error);
  EXPECT_THROW(f.read(1), std::logic_error);
  f.update();
  EXPECT_EQ(f.occupancy(), 0);
  const auto s = f.stats(4);  // cycles 0..3: empty, full, empty, empty
  EXPECT_EQ(s.full_cycles, 1);
  EXPECT_EQ(s.empty_cycles, 3);
  EXPECT_DOUBLE_EQ(s.mean_occupancy, 0.25);
}
