#include "ArpPipelineTop.hpp"

#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

using namespace sc_core;

RunWindow run_window(const cycle::PipelineKernels& k, const dp::ArpConfig& c) {
  RunWindow w;
  const auto& t = k.scan.timing();
  w.first_cycle = k.scan.first_cycle();
  w.end_cycle = k.scan.end_cycle();
  w.base_ps = t.cycles_to_ps(w.first_cycle);
  w.end_ps = t.cycles_to_ps(w.end_cycle);
  w.first_host_cycle = dp::clock_cycle_at_or_after(w.base_ps, c.timed.host_clock_hz);
  w.end_host_cycle = dp::clock_cycle_at_or_after(w.end_ps, c.timed.host_clock_hz);
  return w;
}

ArpPipelineTop::ArpPipelineTop(sc_module_name name, cycle::PipelineKernels& k, const dp::ArpConfig& c,
                               const dp::OrientationStream& o, const RunWindow& w)
    : sc_module(name),
      k_(k),
      pixel_clk("pixel_clk"),
      host_clk("host_clk"),
      pixel_clock("pixel_clock", c.timing.pixel_clock_hz, w.base_ps, w.first_cycle, w.end_cycle),
      host_clock("host_clock", c.timed.host_clock_hz, w.base_ps, w.first_host_cycle, w.end_host_cycle),
      tracker("tracker_interface", o, w.base_ps, w.end_ps),
      pixel_requests("pixel_requests", c.timed.fifo_depth),
      view_vectors("view_vectors", c.timed.fifo_depth),
      world_vectors("world_vectors", c.timed.fifo_depth),
      cube_addresses("cube_addresses", c.timed.fifo_depth),
      texel_words("texel_words", c.timed.fifo_depth),
      composed_taps("composed_taps", c.timed.fifo_depth),
      pixel_colors("pixel_colors", c.timed.fifo_depth),
      timing("video_timing_generator", k, pixel_clock.cycle_ref()),
      lens("lens_vector_table", k, pixel_clock.cycle_ref()),
      orientation("orientation_matrix_unit", k, pixel_clock.cycle_ref()),
      address("cube_face_address_generator", k, pixel_clock.cycle_ref()),
      memories("display_memory_banks", k, pixel_clock.cycle_ref(), host_clock.cycle_ref()),
      composition("composition_unit", k, pixel_clock.cycle_ref()),
      filter("anti_aliasing_filter", k, pixel_clock.cycle_ref()),
      scan_out("hmd_scan_out", k, pixel_clock.cycle_ref()) {
  host_clock.gate([&k](int64_t n) { return k.host.next_active_cycle(n); });
  // The pixel clock is gated while the pipeline is empty and nothing is due
  // (most of the blanking): those clocks would change nothing.
  pixel_clock.gate([this, &k, w](int64_t n) { return tracing_ || !idle() ? n : k.next_busy_cycle(n, w.end_cycle); });
  pixel_clock.clk(pixel_clk);
  host_clock.clk(host_clk);
  timing.clk(pixel_clk);
  lens.clk(pixel_clk);
  orientation.clk(pixel_clk);
  address.clk(pixel_clk);
  memories.clk(pixel_clk);
  memories.host_clk(host_clk);
  composition.clk(pixel_clk);
  filter.clk(pixel_clk);
  scan_out.clk(pixel_clk);

  timing.pixel_requests_out(pixel_requests);
  lens.pixel_requests_in(pixel_requests);
  lens.view_vectors_out(view_vectors);
  orientation.view_vectors_in(view_vectors);
  orientation.world_vectors_out(world_vectors);
  address.world_vectors_in(world_vectors);
  address.cube_addresses_out(cube_addresses);
  memories.cube_addresses_in(cube_addresses);
  memories.texel_words_out(texel_words);
  composition.texel_words_in(texel_words);
  composition.composed_taps_out(composed_taps);
  filter.composed_taps_in(composed_taps);
  filter.pixel_colors_out(pixel_colors);
  scan_out.pixel_colors_in(pixel_colors);

  pixel_requests.core().start_statistics(w.first_cycle);
  view_vectors.core().start_statistics(w.first_cycle);
  world_vectors.core().start_statistics(w.first_cycle);
  cube_addresses.core().start_statistics(w.first_cycle);
  texel_words.core().start_statistics(w.first_cycle);
  composed_taps.core().start_statistics(w.first_cycle);
  pixel_colors.core().start_statistics(w.first_cycle);
}

bool ArpPipelineTop::idle() const {
  return pixel_requests.core().occupancy() == 0 && view_vectors.core().occupancy() == 0 &&
         world_vectors.core().occupancy() == 0 && cube_addresses.core().occupancy() == 0 &&
         texel_words.core().occupancy() == 0 && composed_taps.core().occupancy() == 0 &&
         pixel_colors.core().occupancy() == 0 && k_.stages_idle();
}

void ArpPipelineTop::trace(sc_trace_file* tf) {
  tracing_ = true;
  k_.set_tracing(true);
  const std::string n = name();
  sc_trace(tf, pixel_clk, n + ".pixel_clk");
  sc_trace(tf, host_clk, n + ".host_clk");
  sc_trace(tf, pixel_clock.cycle_ref(), n + ".pixel_cycle");
  timing.trace(tf);
  tracker.trace(tf);
  lens.trace(tf);
  orientation.trace(tf);
  address.trace(tf);
  memories.trace(tf);
  composition.trace(tf);
  filter.trace(tf);
  scan_out.trace(tf);
  sc_trace(tf, pixel_requests.core().occupancy_ref(), n + ".pixel_requests.occupancy");
  sc_trace(tf, view_vectors.core().occupancy_ref(), n + ".view_vectors.occupancy");
  sc_trace(tf, world_vectors.core().occupancy_ref(), n + ".world_vectors.occupancy");
  sc_trace(tf, cube_addresses.core().occupancy_ref(), n + ".cube_addresses.occupancy");
  sc_trace(tf, texel_words.core().occupancy_ref(), n + ".texel_words.occupancy");
  sc_trace(tf, composed_taps.core().occupancy_ref(), n + ".composed_taps.occupancy");
  sc_trace(tf, pixel_colors.core().occupancy_ref(), n + ".pixel_colors.occupancy");
}

std::vector<std::pair<std::string, cycle::FifoStats>> ArpPipelineTop::fifo_stats(int64_t end_cycle) const {
  return {{"pixel_requests", pixel_requests.core().stats(end_cycle)},
          {"view_vectors", view_vectors.core().stats(end_cycle)},
          {"world_vectors", world_vectors.core().stats(end_cycle)},
          {"cube_addresses", cube_addresses.core().stats(end_cycle)},
          {"texel_words", texel_words.core().stats(end_cycle)},
          {"composed_taps", composed_taps.core().stats(end_cycle)},
          {"pixel_colors", pixel_colors.core().stats(end_cycle)}};
}

}  // namespace arp::scm
