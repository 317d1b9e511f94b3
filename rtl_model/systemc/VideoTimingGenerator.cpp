#include "VideoTimingGenerator.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

VideoTimingGenerator::VideoTimingGenerator(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), pixel_requests_out("pixel_requests_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void VideoTimingGenerator::end_of_elaboration() { out_ = pixel_requests_out.operator->(); }

void VideoTimingGenerator::on_clock() { k_.tick_timing(cycle_, *out_); }

void VideoTimingGenerator::trace(sc_trace_file* tf) const {
  const std::string n = name();
  const cycle::ScanTiming& s = k_.scan;
  sc_trace(tf, s.frame_count, n + ".frame");
  sc_trace(tf, s.v_count, n + ".v_count");
  sc_trace(tf, s.h_count, n + ".h_count");
  sc_trace(tf, s.display_enable, n + ".display_enable");
  sc_trace(tf, s.hsync, n + ".hsync");
  sc_trace(tf, s.vsync, n + ".vsync");
  sc_trace(tf, s.vblank, n + ".vblank");
  sc_trace(tf, s.issued, n + ".valid_out");
  sc_trace(tf, s.backlog, n + ".issue_backlog");
}

}  // namespace arp::scm
