#include "ArpPipelineTop.hpp"

#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

RunWindow run_window(const stage::VideoTimingStage& timing, const dp::ArpConfig& c) {
  RunWindow w;
  const auto& t = timing.scan().timing();
  w.first_cycle = timing.first_cycle();
  w.end_cycle = timing.end_cycle();
  w.base_ps = t.cycles_to_ps(w.first_cycle);
  w.end_ps = t.cycles_to_ps(w.end_cycle);
  w.first_host_cycle = dp::clock_cycle_at_or_after(w.base_ps, c.timed.host_clock_hz);
  w.end_host_cycle = dp::clock_cycle_at_or_after(w.end_ps, c.timed.host_clock_hz);
  return w;
}

}  // namespace arp::scm
