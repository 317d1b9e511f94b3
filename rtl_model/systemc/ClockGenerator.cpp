#include "ClockGenerator.hpp"

#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

using namespace sc_core;

ClockGenerator::ClockGenerator(sc_module_name name, int64_t hz, int64_t base_ps, int64_t first_cycle,
                               int64_t end_cycle)
    : sc_module(name), clk("clk"), hz_(hz), base_ps_(base_ps), end_(end_cycle), cycle_(first_cycle - 1) {
  SC_METHOD(edge);  // runs once at initialisation to schedule the first edge
}

int64_t ClockGenerator::edge_ps(int64_t n) const { return dp::clock_cycle_to_ps(n, hz_); }

// The next rising edge: cycle_ + 1, or later if the gate says nothing needs a clock before.
void ClockGenerator::schedule_rise(const sc_time& now) {
  if (gate_) {
    const int64_t n = gate_(cycle_ + 1);
    if (n >= end_) return;
    cycle_ = n - 1;
  }
  if (cycle_ + 1 < end_) next_trigger(sim_time(edge_ps(cycle_ + 1), base_ps_) - now);
}

void ClockGenerator::edge() {
  const sc_time now = sc_time_stamp();
  if (!started_) {
    started_ = true;
    schedule_rise(now);
    return;
  }
  if (!high_) {
    ++cycle_;
    high_ = true;
    clk.write(true);
    const int64_t rise = edge_ps(cycle_), next = edge_ps(cycle_ + 1);
    next_trigger(sim_time(rise + (next - rise) / 2, base_ps_) - now);
  } else {
    high_ = false;
    clk.write(false);
    schedule_rise(now);
  }
}

}  // namespace arp::scm
