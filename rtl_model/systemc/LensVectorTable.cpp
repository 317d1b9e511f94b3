#include "LensVectorTable.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

LensVectorTable::LensVectorTable(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), pixel_requests_in("pixel_requests_in"), view_vectors_out("view_vectors_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void LensVectorTable::end_of_elaboration() {
  in_ = pixel_requests_in.operator->();
  out_ = view_vectors_out.operator->();
}

void LensVectorTable::on_clock() { k_.tick_lens(cycle_, *in_, *out_); }

void LensVectorTable::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.lens.ready_in, n + ".ready_in");
  sc_trace(tf, k_.lens.valid_out, n + ".valid_out");
  sc_trace(tf, k_.lens.data_out[0], n + ".view_x");
  sc_trace(tf, k_.lens.data_out[1], n + ".view_y");
  sc_trace(tf, k_.lens.data_out[2], n + ".view_z");
}

}  // namespace arp::scm
