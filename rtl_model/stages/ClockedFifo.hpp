// A clocked FIFO with a valid/ready handshake, as a plain C++ core shared by
// every cycle-accurate level. Both ends see the state at the start of the
// clock: a write becomes readable, and a read frees its place, only at
// update() (the clock edge), so the order in which stages are evaluated
// within a cycle cannot matter. Writing when not ready is a modelling bug and
// throws -- data is never dropped silently.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "PixelTokens.hpp"
#include "RingIndex.hpp"

// The FIFO operations run several times per pixel clock: always inline (the
// fast level ticks every stage in one function, past the inliner's budget).
#define ARP_FIFO_OP __attribute__((always_inline)) inline

namespace arp::stage {

struct FifoStats {
  int depth = 0;
  int64_t writes = 0, reads = 0;
  int max_occupancy = 0;
  double mean_occupancy = 0;  // over the cycles observed
  int64_t full_cycles = 0, empty_cycles = 0;
  int64_t blocked_writes = 0;  // cycles a producer held data but the FIFO was full
};

template <class T>
class ClockedFifo {
 public:
  ClockedFifo(std::string name, int depth) : name_(std::move(name)), buf_(static_cast<size_t>(depth)), depth_(depth) {}

  const std::string& name() const { return name_; }
  int depth() const { return depth_; }
  int occupancy() const { return count_; }
  const int& occupancy_ref() const { return count_; }  // for waveform tracing

  // Producer side: ready = not full at the start of the cycle.
  ARP_FIFO_OP bool can_write() const { return count_ < depth_ && !write_pending_; }
  ARP_FIFO_OP void write(const T& v, int64_t cycle) {
    if (!can_write()) throw std::logic_error(name_ + ": write while not ready (full)");
    copy_token(buf_[ring_index(head_ + static_cast<size_t>(count_), slots())], v);
    write_pending_ = true;
    cycle_ = cycle;
  }
  // Write in place: the slot the next write would fill (fill it, then nothing
  // else) -- a stage with one register can compute straight into its output.
  ARP_FIFO_OP T& emplace(int64_t cycle) {
    if (!can_write()) throw std::logic_error(name_ + ": write while not ready (full)");
    write_pending_ = true;
    cycle_ = cycle;
    return buf_[ring_index(head_ + static_cast<size_t>(count_), slots())];
  }
  void note_blocked() { ++blocked_; }

  // Consumer side: valid = not empty at the start of the cycle.
  ARP_FIFO_OP bool can_read() const { return count_ > 0 && !read_pending_; }
  ARP_FIFO_OP const T& front() const { return buf_[head_]; }
  ARP_FIFO_OP void read(int64_t cycle) {
    if (!can_read()) throw std::logic_error(name_ + ": read while not valid (empty)");
    read_pending_ = true;
    cycle_ = cycle;
  }

  // The clock edge ending cycle `cycle_`: applies this cycle's read and write.
  // The occupancy statistics change only with the occupancy: a read and a
  // write in one clock (a streaming FIFO's every clock) leave them to the next
  // change, which accounts for the cycles since the last (account()).
  ARP_FIFO_OP void update() {
    if (!read_pending_ && !write_pending_) return;
    if (read_pending_) {
      head_ = ring_index(head_ + 1, slots());
      ++reads_;
    }
    if (write_pending_) ++writes_;
    if (read_pending_ != write_pending_) {
      account(cycle_ + 1);
      count_ += write_pending_ ? 1 : -1;
      if (count_ > max_) max_ = count_;
    }
    read_pending_ = write_pending_ = false;
  }

  // Statistics over cycles [first observed, end_cycle).
  FifoStats stats(int64_t end_cycle) const {
    FifoStats s;
    s.depth = depth_;
    s.writes = writes_;
    s.reads = reads_;
    s.max_occupancy = max_;
    const int64_t tail = end_cycle > since_ ? end_cycle - since_ : 0;
    const double area = static_cast<double>(area_) + static_cast<double>(count_) * static_cast<double>(tail);
    const int64_t span = end_cycle - start_;
    s.mean_occupancy = span > 0 ? area / static_cast<double>(span) : 0.0;
    s.full_cycles = full_ + (count_ == depth_ ? tail : 0);
    s.empty_cycles = empty_ + (count_ == 0 ? tail : 0);
    s.blocked_writes = blocked_;
    return s;
  }
  void start_statistics(int64_t cycle) { start_ = since_ = cycle; }

 private:
  // Adds the occupancy held since the last change, up to cycle c.
  void account(int64_t c) {
    const int64_t span = c - since_;
    if (span <= 0) return;
    area_ += static_cast<int64_t>(count_) * span;
    if (count_ == depth_) full_ += span;
    if (count_ == 0) empty_ += span;
    since_ = c;
  }

  // The ring's size, the depth: a vector's size() divides its byte length by sizeof(T), a
  // multiply for most tokens, several times a clock.
  size_t slots() const { return static_cast<size_t>(depth_); }

  std::string name_;
  std::vector<T> buf_;
  size_t head_ = 0;
  int depth_;
  int count_ = 0;
  bool write_pending_ = false, read_pending_ = false;
  int64_t cycle_ = 0;
  int64_t writes_ = 0, reads_ = 0, blocked_ = 0;
  int max_ = 0;
  int64_t area_ = 0, full_ = 0, empty_ = 0, since_ = 0, start_ = 0;
};

}  // namespace arp::stage
