// A bench for one pipeline stage module: a stimulus driver feeding its input
// FIFO and a response monitor draining its output FIFO, on one clock. The
// first half of the stimulus is driven back to back with the monitor always
// ready, so each pixel must take exactly the stage's latency; the second half
// has seeded-random gaps and backpressure, so order and data must survive
// stalls. The scoreboard is the test's: it compares what the monitor got
// against the datapath functions (and the golden reference) item by item.
#pragma once
#include <systemc>

#include <cstdint>
#include <random>
#include <vector>

#include "rtl_model/systemc/ClockGenerator.hpp"
#include "rtl_model/systemc/FifoChannel.hpp"

namespace arp::bench {

// A bench module that acts at each rising edge of the pixel clock: a clock
// port and one method process calling on_clock(the cycle).
class ClockedBenchModule : public sc_core::sc_module {
 public:
  sc_core::sc_port<scm::ClockIf> clk;

 protected:
  SC_HAS_PROCESS(ClockedBenchModule);
  explicit ClockedBenchModule(sc_core::sc_module_name n) : sc_module(n), clk("clk") {
    SC_METHOD(tick);
    sensitive << clk;
    dont_initialize();
  }
  virtual void on_clock(int64_t cycle) = 0;

 private:
  void tick() { on_clock(clk->cycle()); }
};

template <class T>
class StimulusDriver : public ClockedBenchModule {
 public:
  sc_core::sc_port<scm::FifoWriteIf<T>> stimulus_out;

  StimulusDriver(sc_core::sc_module_name n, std::vector<T> items, uint32_t seed)
      : ClockedBenchModule(n), stimulus_out("stimulus_out"), items_(std::move(items)), rng_(seed) {}
  std::vector<int64_t> write_cycle;  // per item
  size_t phase_one() const { return items_.size() / 2; }
  int64_t start_cycle = 0;           // nothing is driven before this cycle
  int64_t phase_two_cycle = 0;       // nor the second half before this one

 private:
  void on_clock(int64_t cycle) override {
    if (cycle < start_cycle || next_ >= items_.size()) return;
    if (next_ >= phase_one() && cycle < phase_two_cycle) return;
    if (next_ >= phase_one() && std::bernoulli_distribution(0.3)(rng_)) return;  // a gap
    if (!stimulus_out->can_write()) return;
    stimulus_out->write(items_[next_++], cycle);
    write_cycle.push_back(cycle);
  }
  std::vector<T> items_;
  std::mt19937 rng_;
  size_t next_ = 0;
};

template <class T>
class ResponseMonitor : public ClockedBenchModule {
 public:
  sc_core::sc_port<scm::FifoReadIf<T>> response_in;

  ResponseMonitor(sc_core::sc_module_name n, size_t phase_one, uint32_t seed)
      : ClockedBenchModule(n), response_in("response_in"), phase_one_(phase_one), rng_(seed) {}
  std::vector<T> got;
  std::vector<int64_t> read_cycle;

 private:
  void on_clock(int64_t cycle) override {
    if (!response_in->can_read()) return;
    if (got.size() >= phase_one_ && std::bernoulli_distribution(0.3)(rng_)) return;  // backpressure
    got.push_back(response_in->front());
    read_cycle.push_back(cycle);
    response_in->read(cycle);
  }
  size_t phase_one_;
  std::mt19937 rng_;
};

}  // namespace arp::bench
