#include "FunctionalStandIn.hpp"

#include "ClockGenerator.hpp"

namespace arp::scm {

using namespace sc_core;

FunctionalStandIn::FunctionalStandIn(sc_module_name name, const stage::TimedInputs& in, int64_t base_ps, int threads)
    : sc_module(name),
      in_(in),
      frames_(in, threads),
      timing_(in.config.timing),
      base_ps_(base_ps),
      end_frame_(in.first_frame + in.frames),
      frame_(next_untimed(in.first_frame)) {
  SC_METHOD(next);  // runs at the start, then at each untimed frame's start
}

int64_t FunctionalStandIn::next_untimed(int64_t from) const {
  while (from < end_frame_ && in_.timed_frames.contains(from)) ++from;
  return from;
}

void FunctionalStandIn::next() {
  if (frame_ >= end_frame_) return;
  const sc_time start = sim_time(timing_.cycles_to_ps(timing_.frame_start_cycle(frame_)), base_ps_);
  const sc_time now = sc_time_stamp();
  if (now < start) {
    next_trigger(start - now);
    return;
  }
  const stage::FrameReport r = frames_.render(frame_);
  ++done_;
  frame_ = next_untimed(frame_ + 1);
  if (frame_ < end_frame_) next_trigger(sim_time(timing_.cycles_to_ps(timing_.frame_start_cycle(frame_)), base_ps_) - now);
  if (in_.sink) in_.sink(frames_.frame(), r);  // last: the sink may end the run (sc_stop)
}

}  // namespace arp::scm
