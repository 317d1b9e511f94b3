// A pipeline stage's register stages: an elastic pipe of `latency` slots.
// A pixel taken from the input FIFO at cycle c is handed to the output FIFO
// at cycle c + latency - 1 (visible to the next stage at c + latency) unless
// the output is not ready, in which case it waits and the pipe fills; a
// full pipe stops taking input, which is how backpressure travels upstream.
// The arithmetic runs when a pixel enters; only its timing is modelled here.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "PixelTokens.hpp"
#include "RingIndex.hpp"

namespace arp::stage {

struct StageStats {
  int latency_cycles = 0;    // configured
  int64_t pixels = 0;
  int64_t min_cycles = 0, max_cycles = 0;  // measured: input taken -> visible downstream
  double mean_cycles = 0;
  int64_t stalled_cycles = 0;   // a finished pixel waited for a full output FIFO
  int64_t forced_stall_cycles = 0;  // stalls injected by a test or experiment
};

template <class Out>
class StagePipe {
 public:
  explicit StagePipe(int latency) : latency_(latency), ring_(static_cast<size_t>(latency) + 1), slots_(ring_.size()) {}

  int latency() const { return latency_; }
  int occupancy() const { return count_; }

  // One clock. `compute(const In&, Out&)` is the stage's datapath call, filling the slot in place.
  // `forced_stall`: the stage does nothing this cycle (an injected stall).
  template <class InFifo, class OutFifo, class Fn>
  void tick(int64_t cycle, InFifo& in, OutFifo& out, Fn&& compute, bool forced_stall = false) {
    valid_out = false;
    if (forced_stall) {
      ++forced_;
      ready_in = false;
      return;
    }
    if (latency_ == 1 && count_ == 0 && in.can_read() && out.can_write()) {
      // One register: the result goes straight into the output FIFO (no copy).
      ready_in = true;
      Out& o = out.emplace(cycle);
      compute(in.front(), o);
      in.read(cycle);
      record(1);
      if (probe_data) probe(o, data_out);
      valid_out = true;
      return;
    }
    const bool head_done = count_ > 0 && oldest().done <= cycle;
    const bool out_ready = out.can_write();
    const bool pops = head_done && out_ready;
    ready_in = count_ < latency_ || pops;
    if (ready_in && in.can_read()) {
      Entry& e = ring_[ring_index(head_ + static_cast<size_t>(count_), slots_)];
      compute(in.front(), e.value);
      e.taken = cycle;
      e.done = cycle + latency_ - 1;
      in.read(cycle);
      ++count_;
    }
    if (count_ > 0 && oldest().done <= cycle) {
      if (out.can_write()) {
        const Entry& e = oldest();
        out.write(e.value, cycle);
        if (probe_data) probe(e.value, data_out);
        record(cycle + 1 - e.taken);
        head_ = ring_index(head_ + 1, slots_);
        --count_;
        valid_out = true;
      } else {
        ++stalled_;
        out.note_blocked();
      }
    }
  }

  StageStats stats() const {
    StageStats s;
    s.latency_cycles = latency_;
    s.pixels = n_;
    const int64_t on_time = n_ - other_n_, L = latency_;
    s.min_cycles = n_ ? std::min(other_n_ ? min_ : L, on_time ? L : min_) : 0;
    s.max_cycles = n_ ? std::max(other_n_ ? max_ : L, on_time ? L : max_) : 0;
    const int64_t sum = on_time * L + other_sum_;
    s.mean_cycles = n_ ? static_cast<double>(sum) / static_cast<double>(n_) : 0.0;
    s.stalled_cycles = stalled_;
    s.forced_stall_cycles = forced_;
    return s;
  }

  // Traced handshake -- a pixel left this cycle / the stage could take one --
  // and the last pixel's data (see probe() in PixelTokens.hpp).
  bool valid_out = false, ready_in = true;
  std::array<int64_t, 3> data_out{};
  bool probe_data = false;  // set while a waveform is traced

 private:
  struct Entry {
    Out value{};
    int64_t taken = 0, done = 0;
  };
  const Entry& oldest() const { return ring_[head_]; }  // head_ is always a slot: no ring arithmetic
  // A pixel visible downstream c clocks after it was taken. Most take exactly the latency: only
  // the others are summed and compared (stats() adds the rest back).
  void record(int64_t c) {
    ++n_;
    if (c == latency_) return;
    ++other_n_;
    other_sum_ += c;
    min_ = std::min(min_, c);
    max_ = std::max(max_, c);
  }

  int latency_;
  std::vector<Entry> ring_;
  size_t slots_;  // ring_.size(), kept: size() divides by sizeof(Entry), a multiply, several times a clock
  size_t head_ = 0;
  int count_ = 0;
  int64_t n_ = 0, other_n_ = 0, other_sum_ = 0, min_ = std::numeric_limits<int64_t>::max(), max_ = 0;
  int64_t stalled_ = 0, forced_ = 0;
};

}  // namespace arp::stage
