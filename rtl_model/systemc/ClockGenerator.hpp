// A clock with exact edges, as a channel: cycle n rises at floor(n * 1e12 /
// hz) ps of absolute time, so a 25.175 MHz pixel clock (39721.9... ps) never
// drifts from the datapath's VideoTiming; edges jitter by under 1 ps instead.
// Modules bind a port to it (sc_port<ClockIf>), are sensitive to its rising
// edge (or run by it: attach) and read the cycle number from it -- no module
// shares another's counter. Simulated time 0 is absolute time `base_ps` (a
// run may start before 0). The falling edge exists only for the waveform: while no trace
// shows the clock, each cycle costs one activation.
#pragma once
#include <systemc>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rtl_model/datapath/ClockTime.hpp"

namespace arp::scm {

// Simulated time of absolute ps (which must not precede the base).
inline sc_core::sc_time sim_time(int64_t abs_ps, int64_t base_ps) {
  return sc_core::sc_time::from_value(static_cast<sc_core::sc_time::value_type>(abs_ps - base_ps));
}

class ClockIf : virtual public sc_core::sc_interface {
 public:
  // The current cycle: the one whose rising edge came last.
  virtual int64_t cycle() const = 0;
  virtual const sc_core::sc_event& posedge_event() const = 0;
  const sc_core::sc_event& default_event() const override { return posedge_event(); }
};

// What a clocked module does at each rising edge, when the generator runs it
// itself (ClockGenerator::attach) rather than the kernel as a process of its own.
class RisingEdgeCallee {
 public:
  virtual void on_rising_edge() = 0;

 protected:
  ~RisingEdgeCallee() = default;
};

class ClockGenerator final : public sc_core::sc_module, public ClockIf {
 public:
  SC_HAS_PROCESS(ClockGenerator);
  // Rising edges of cycles [first_cycle, end_cycle).
  ClockGenerator(sc_core::sc_module_name name, int64_t hz, int64_t base_ps, int64_t first_cycle, int64_t end_cycle);

  // Clock gating: before each rising edge, the generator asks for the first
  // cycle at or after the next one that needs a clock and skips to it.
  void gate(std::function<int64_t(int64_t)> next_needed) { gate_ = std::move(next_needed); }

  // Before the simulation starts: `callee` runs at each rising edge, in the order attached, inside the
  // generator's own activation -- the evaluation phase in which a process statically sensitive to the
  // edge would run, without the kernel's trigger, queue and dispatch of one process per module and clock
  // (about 100 host instructions each in SystemC 2.3.4). The edge's event is still notified for the
  // processes that wait on it, once one has asked for it (posedge_event).
  void attach(RisingEdgeCallee& callee);

  int64_t cycle() const override { return cycle_; }
  int64_t rising_edges() const { return edges_; }  // the cycles clocked (what gating skipped is not among them)
  // Whoever waits on the edge's event asks for it here first (a port's static sensitivity through
  // default_event, at elaboration), so the edge is notified only once someone has: an immediate
  // notification with no process to wake still costs the kernel some 60 instructions a clock.
  const sc_core::sc_event& posedge_event() const override {
    listened_ = true;
    return posedge_;
  }
  // Waveforms: the clock level (with its falling edge, until stop_trace()), the cycle number.
  void trace(sc_core::sc_trace_file* tf, const std::string& name);
  void trace_cycle(sc_core::sc_trace_file* tf, const std::string& name) const;
  void stop_trace() { traced_ = false; }

 private:
  void edge();
  int64_t edge_ps(int64_t n) const;
  std::function<int64_t(int64_t)> gate_;
  std::vector<RisingEdgeCallee*> callees_;
  sc_core::sc_event posedge_, wake_;
  int64_t base_ps_, end_;
  mutable dp::ClockTimeCursor clock_;  // edges are asked for in order: no 128-bit division each
  int64_t cycle_;
  int64_t edges_ = 0;
  bool started_ = false, level_ = false, traced_ = false, skipped_ = false;
  mutable bool listened_ = false;  // posedge_event() was asked for
};

}  // namespace arp::scm
