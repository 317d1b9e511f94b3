#include "HmdScanOut.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

HmdScanOut::HmdScanOut(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), pixel_colors_in("pixel_colors_in"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void HmdScanOut::end_of_elaboration() { in_ = pixel_colors_in.operator->(); }

void HmdScanOut::on_clock() { k_.tick_scanout(cycle_, *in_); }

void HmdScanOut::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.scanout.display_valid, n + ".display_valid");
  sc_trace(tf, k_.scanout.display_rgb, n + ".display_rgb");
  sc_trace(tf, k_.scanout.underflow_count, n + ".underflows");
}

}  // namespace arp::scm
