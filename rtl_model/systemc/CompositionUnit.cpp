#include "CompositionUnit.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

CompositionUnit::CompositionUnit(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), texel_words_in("texel_words_in"), composed_taps_out("composed_taps_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void CompositionUnit::end_of_elaboration() {
  in_ = texel_words_in.operator->();
  out_ = composed_taps_out.operator->();
}

void CompositionUnit::on_clock() { k_.tick_compose(cycle_, *in_, *out_); }

void CompositionUnit::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.compose.ready_in, n + ".ready_in");
  sc_trace(tf, k_.compose.valid_out, n + ".valid_out");
  sc_trace(tf, k_.compose.data_out[0], n + ".color_tap0");
  sc_trace(tf, k_.compose.data_out[1], n + ".color_tap1");
  sc_trace(tf, k_.compose.data_out[2], n + ".weight_x");
}

}  // namespace arp::scm
