#include "AntiAliasingFilter.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

AntiAliasingFilter::AntiAliasingFilter(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), composed_taps_in("composed_taps_in"), pixel_colors_out("pixel_colors_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void AntiAliasingFilter::end_of_elaboration() {
  in_ = composed_taps_in.operator->();
  out_ = pixel_colors_out.operator->();
}

void AntiAliasingFilter::on_clock() { k_.tick_filter(cycle_, *in_, *out_); }

void AntiAliasingFilter::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.filter.ready_in, n + ".ready_in");
  sc_trace(tf, k_.filter.valid_out, n + ".valid_out");
  sc_trace(tf, k_.filter.data_out[0], n + ".color");
  sc_trace(tf, k_.filter.data_out[1], n + ".x");
  sc_trace(tf, k_.filter.data_out[2], n + ".y");
}

}  // namespace arp::scm
