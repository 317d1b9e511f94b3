#include "OrientationMatrixUnit.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

OrientationMatrixUnit::OrientationMatrixUnit(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), view_vectors_in("view_vectors_in"), world_vectors_out("world_vectors_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void OrientationMatrixUnit::end_of_elaboration() {
  in_ = view_vectors_in.operator->();
  out_ = world_vectors_out.operator->();
}

void OrientationMatrixUnit::on_clock() { k_.tick_rotate(cycle_, *in_, *out_); }

void OrientationMatrixUnit::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.rotate.ready_in, n + ".ready_in");
  sc_trace(tf, k_.rotate.valid_out, n + ".valid_out");
  sc_trace(tf, k_.rotate.data_out[0], n + ".world_x");
  sc_trace(tf, k_.rotate.data_out[1], n + ".world_y");
  sc_trace(tf, k_.rotate.data_out[2], n + ".world_z");
  sc_trace(tf, k_.latch.sample, n + ".matrix_sample");
  for (int i = 0; i < 9; ++i) sc_trace(tf, k_.latch.matrix.m[i], n + ".matrix_" + std::to_string(i / 3) + std::to_string(i % 3));
}

}  // namespace arp::scm
