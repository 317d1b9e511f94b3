#include "VideoTimingGenerator.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

VideoTimingGenerator::VideoTimingGenerator(sc_module_name name, const stage::StageContext& ctx)
    : sc_module(name), clk("clk"), pixel_requests_out("pixel_requests_out"), stage_(ctx) {
  SC_METHOD(on_clock);
  sensitive << clk;
  dont_initialize();
}

void VideoTimingGenerator::trace(sc_trace_file* tf) {
  stage_.track_position = true;
  const std::string n = name();
  const stage::VideoTimingStage& s = stage_;
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
