// A clock with exact edges: cycle n rises at floor(n * 1e12 / hz) ps of
// absolute time, so a 25.175 MHz pixel clock (39721.9... ps) never drifts
// from the datapath's VideoTiming; edges jitter by under 1 ps instead.
// Simulated time 0 is absolute time `base_ps` (a run may start before 0).
#pragma once
#include <systemc>

#include <cstdint>
#include <functional>

namespace arp::scm {

// Simulated time of absolute ps (which must not precede the base).
inline sc_core::sc_time sim_time(int64_t abs_ps, int64_t base_ps) {
  return sc_core::sc_time::from_value(static_cast<sc_core::sc_time::value_type>(abs_ps - base_ps));
}

class ClockGenerator : public sc_core::sc_module {
 public:
  sc_core::sc_out<bool> clk;

  SC_HAS_PROCESS(ClockGenerator);
  // Rising edges of cycles [first_cycle, end_cycle); `cycle()` is the current one after each.
  ClockGenerator(sc_core::sc_module_name name, int64_t hz, int64_t base_ps, int64_t first_cycle, int64_t end_cycle);

  // Clock gating: before each rising edge, the generator asks for the first
  // cycle at or after the next one that needs a clock and skips to it.
  void gate(std::function<int64_t(int64_t)> next_needed) { gate_ = std::move(next_needed); }

  int64_t cycle() const { return cycle_; }
  const int64_t& cycle_ref() const { return cycle_; }

 private:
  void edge();
  void schedule_rise(const sc_core::sc_time& now);
  int64_t edge_ps(int64_t n) const;
  std::function<int64_t(int64_t)> gate_;
  int64_t hz_, base_ps_, end_;
  int64_t cycle_;
  bool started_ = false, high_ = false;
};

}  // namespace arp::scm
