#include "FastCycleModel.hpp"

#include <algorithm>

#include "ClockGenerator.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

using namespace sc_core;

FastCycleModel::FastCycleModel(sc_module_name name, cycle::PipelineKernels& k, const dp::ArpConfig& c,
                               const dp::OrientationStream& o, const RunWindow& w)
    : sc_module(name),
      k_(k),
      w_(w),
      pixel_hz_(c.timing.pixel_clock_hz),
      host_hz_(c.timed.host_clock_hz),
      tracker("tracker_interface", o, w.base_ps, w.end_ps),
      pixel_requests_("pixel_requests", c.timed.fifo_depth),
      view_vectors_("view_vectors", c.timed.fifo_depth),
      world_vectors_("world_vectors", c.timed.fifo_depth),
      cube_addresses_("cube_addresses", c.timed.fifo_depth),
      texel_words_("texel_words", c.timed.fifo_depth),
      composed_taps_("composed_taps", c.timed.fifo_depth),
      pixel_colors_("pixel_colors", c.timed.fifo_depth),
      cycle_(w.first_cycle),
      host_cycle_(w.first_host_cycle) {
  pixel_requests_.start_statistics(w.first_cycle);
  view_vectors_.start_statistics(w.first_cycle);
  world_vectors_.start_statistics(w.first_cycle);
  cube_addresses_.start_statistics(w.first_cycle);
  texel_words_.start_statistics(w.first_cycle);
  composed_taps_.start_statistics(w.first_cycle);
  pixel_colors_.start_statistics(w.first_cycle);
  SC_METHOD(pixel_domain);
  SC_METHOD(host_domain);
}

bool FastCycleModel::idle() const {
  return pixel_requests_.occupancy() == 0 && view_vectors_.occupancy() == 0 && world_vectors_.occupancy() == 0 &&
         cube_addresses_.occupancy() == 0 && texel_words_.occupancy() == 0 && composed_taps_.occupancy() == 0 &&
         pixel_colors_.occupancy() == 0 && k_.stages_idle();
}

// One pixel clock: every stage, then the clock edge of every FIFO.
void FastCycleModel::evaluate(int64_t c) {
  k_.tick_timing(c, pixel_requests_);
  k_.tick_lens(c, pixel_requests_, view_vectors_);
  k_.tick_rotate(c, view_vectors_, world_vectors_);
  k_.tick_address(c, world_vectors_, cube_addresses_);
  k_.tick_fetch(c, cube_addresses_, texel_words_);
  k_.tick_compose(c, texel_words_, composed_taps_);
  k_.tick_filter(c, composed_taps_, pixel_colors_);
  k_.tick_scanout(c, pixel_colors_);
  pixel_requests_.update();
  view_vectors_.update();
  world_vectors_.update();
  cube_addresses_.update();
  texel_words_.update();
  composed_taps_.update();
  pixel_colors_.update();
  ++evaluated_;
}

void FastCycleModel::pixel_domain() {
  const sc_time now = sc_time_stamp();
  if (!started_) {
    started_ = true;
    next_trigger(sim_time(dp::clock_cycle_to_ps(cycle_, pixel_hz_), w_.base_ps) - now);
    return;
  }
  const auto& sched = k_.scan.schedule();
  const int64_t F = k_.scan.timing().frame_cycles();
  // Never run past a swap cycle: it must be evaluated at its own time.
  const int64_t f = (cycle_ - sched.swap_cycle(0)) / F;
  int64_t stop = w_.end_cycle;
  for (int64_t g = f - 1; g <= f + 2; ++g)
    if (sched.swap_cycle(g) > cycle_) stop = std::min(stop, sched.swap_cycle(g));
  if (tracing_) stop = cycle_ + 1;
  else stop = std::min(stop, cycle_ + kBatch);
  int64_t c = cycle_;
  while (c < stop) {
    evaluate(c++);
    if (!tracing_ && c < stop && idle()) c = std::min(stop, k_.next_busy_cycle(c, w_.end_cycle));
  }
  cycle_ = c;
  if (!tracing_ && idle()) cycle_ = k_.next_busy_cycle(cycle_, w_.end_cycle);
  if (cycle_ < w_.end_cycle) next_trigger(sim_time(dp::clock_cycle_to_ps(cycle_, pixel_hz_), w_.base_ps) - now);
}

void FastCycleModel::host_domain() {
  const sc_time now = sc_time_stamp();
  if (host_started_) {
    k_.tick_host(host_cycle_);
    ++host_cycle_;
  }
  host_started_ = true;
  host_cycle_ = k_.host.next_active_cycle(host_cycle_);  // gated while the port is idle
  if (host_cycle_ < w_.end_host_cycle)
    next_trigger(sim_time(dp::clock_cycle_to_ps(host_cycle_, host_hz_), w_.base_ps) - now);
}

void FastCycleModel::trace(sc_trace_file* tf) {
  tracing_ = true;
  k_.set_tracing(true);
  const std::string n = name();
  sc_trace(tf, cycle_, n + ".pixel_cycle");
  const cycle::ScanTiming& s = k_.scan;
  sc_trace(tf, s.frame_count, n + ".video_timing_generator.frame");
  sc_trace(tf, s.v_count, n + ".video_timing_generator.v_count");
  sc_trace(tf, s.h_count, n + ".video_timing_generator.h_count");
  sc_trace(tf, s.display_enable, n + ".video_timing_generator.display_enable");
  sc_trace(tf, s.vblank, n + ".video_timing_generator.vblank");
  sc_trace(tf, s.issued, n + ".video_timing_generator.valid_out");
  tracker.trace(tf);
  sc_trace(tf, k_.latch.sample, n + ".orientation_matrix_unit.matrix_sample");
  sc_trace(tf, k_.swapper.front_select, n + ".display_memory_banks.front_select");
  sc_trace(tf, k_.host.busy, n + ".display_memory_banks.host_busy");
  sc_trace(tf, k_.scanout.display_valid, n + ".hmd_scan_out.display_valid");
  sc_trace(tf, k_.scanout.display_rgb, n + ".hmd_scan_out.display_rgb");
  sc_trace(tf, k_.scanout.underflow_count, n + ".hmd_scan_out.underflows");
  sc_trace(tf, pixel_requests_.occupancy_ref(), n + ".pixel_requests.occupancy");
  sc_trace(tf, view_vectors_.occupancy_ref(), n + ".view_vectors.occupancy");
  sc_trace(tf, world_vectors_.occupancy_ref(), n + ".world_vectors.occupancy");
  sc_trace(tf, cube_addresses_.occupancy_ref(), n + ".cube_addresses.occupancy");
  sc_trace(tf, texel_words_.occupancy_ref(), n + ".texel_words.occupancy");
  sc_trace(tf, composed_taps_.occupancy_ref(), n + ".composed_taps.occupancy");
  sc_trace(tf, pixel_colors_.occupancy_ref(), n + ".pixel_colors.occupancy");
}

std::vector<std::pair<std::string, cycle::FifoStats>> FastCycleModel::fifo_stats(int64_t end_cycle) const {
  return {{"pixel_requests", pixel_requests_.stats(end_cycle)}, {"view_vectors", view_vectors_.stats(end_cycle)},
          {"world_vectors", world_vectors_.stats(end_cycle)},   {"cube_addresses", cube_addresses_.stats(end_cycle)},
          {"texel_words", texel_words_.stats(end_cycle)},       {"composed_taps", composed_taps_.stats(end_cycle)},
          {"pixel_colors", pixel_colors_.stats(end_cycle)}};
}

}  // namespace arp::scm
