#include "CubeFaceAddressGenerator.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

CubeFaceAddressGenerator::CubeFaceAddressGenerator(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : sc_module(name), clk("clk"), world_vectors_in("world_vectors_in"), cube_addresses_out("cube_addresses_out"), k_(k), cycle_(cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
}

void CubeFaceAddressGenerator::end_of_elaboration() {
  in_ = world_vectors_in.operator->();
  out_ = cube_addresses_out.operator->();
}

void CubeFaceAddressGenerator::on_clock() { k_.tick_address(cycle_, *in_, *out_); }

void CubeFaceAddressGenerator::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.address.ready_in, n + ".ready_in");
  sc_trace(tf, k_.address.valid_out, n + ".valid_out");
  sc_trace(tf, k_.address.data_out[0], n + ".face");
  sc_trace(tf, k_.address.data_out[1], n + ".texel_x");
  sc_trace(tf, k_.address.data_out[2], n + ".texel_y");
}

}  // namespace arp::scm
