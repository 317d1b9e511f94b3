#include "HmdScanOut.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

HmdScanOut::HmdScanOut(sc_module_name name, const stage::StageContext& ctx)
    : sc_module(name), clk("clk"), pixel_colors_in("pixel_colors_in"), stage_(ctx) {
  SC_METHOD(on_clock);
  sensitive << clk;
  dont_initialize();
}

void HmdScanOut::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, stage_.display_valid, n + ".display_valid");
  sc_trace(tf, stage_.display_rgb, n + ".display_rgb");
  sc_trace(tf, stage_.underflow_count, n + ".underflows");
}

}  // namespace arp::scm
