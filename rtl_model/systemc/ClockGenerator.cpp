#include "ClockGenerator.hpp"

#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

using namespace sc_core;

ClockGenerator::ClockGenerator(sc_module_name name, int64_t hz, int64_t base_ps, int64_t first_cycle, int64_t end_cycle)
    : sc_module(name), base_ps_(base_ps), end_(end_cycle), clock_(hz), cycle_(first_cycle - 1) {
  // Statically sensitive to its own wake-up event, notified at each next edge: a timed
  // notification of a static event costs the kernel less than a dynamic next_trigger.
  SC_METHOD(edge);  // runs once at initialisation to schedule the first edge
  sensitive << wake_;
}

void ClockGenerator::attach(RisingEdgeCallee& callee) {
  if (sc_is_running()) SC_REPORT_ERROR("arpsim/clock", (std::string(name()) + ": a module attached after the simulation started").c_str());
  callees_.push_back(&callee);
}

int64_t ClockGenerator::edge_ps(int64_t n) const { return clock_.ps(n); }

void ClockGenerator::trace(sc_trace_file* tf, const std::string& name) {
  traced_ = true;
  sc_trace(tf, level_, name);
}

void ClockGenerator::trace_cycle(sc_trace_file* tf, const std::string& name) const { sc_trace(tf, cycle_, name); }

// One activation per edge. A rising edge is decided at its own time: the gate
// is asked then, after every clocked process of the previous cycle has run.
void ClockGenerator::edge() {
  const sc_time now = sc_time_stamp();
  if (!started_) {
    started_ = true;
    wake_.notify(sim_time(edge_ps(cycle_ + 1), base_ps_) - now);
    return;
  }
  if (level_) {  // the falling edge (traced clocks only)
    level_ = false;
    wake_.notify(sim_time(edge_ps(cycle_ + 1), base_ps_) - now);
    return;
  }
  int64_t n = cycle_ + 1;
  if (gate_ && !skipped_) n = gate_(n);
  if (n >= end_) return;
  if (n != cycle_ + 1) {  // nothing needs the clocks in between
    cycle_ = n - 1;
    skipped_ = true;
    wake_.notify(sim_time(edge_ps(n), base_ps_) - now);
    return;
  }
  skipped_ = false;
  ++cycle_;
  ++edges_;
  // Immediate: the clocked processes run in this evaluation phase (the attached modules here), saving
  // the kernel a delta cycle per clock. Their order against the other processes of this instant, and
  // the attached modules' among themselves, cannot matter: they talk
  // through FIFOs settled at the update phase; the orientation register is read by time
  // (dp::register_sample); the buffer swap takes only commits strictly before its blank, so a host
  // port commit in this same instant is not among them, whichever process runs first.
  if (listened_) posedge_.notify();
  for (RisingEdgeCallee* c : callees_) c->on_rising_edge();
  if (traced_) {
    level_ = true;
    const int64_t rise = edge_ps(cycle_), next = edge_ps(cycle_ + 1);
    wake_.notify(sim_time(rise + (next - rise) / 2, base_ps_) - now);
  } else if (cycle_ + 1 < end_) {
    wake_.notify(sim_time(edge_ps(cycle_ + 1), base_ps_) - now);
  }
}

}  // namespace arp::scm
