// Cube-face address generator: rotated direction to face, texel and sub-texel position.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class CubeFaceAddressGenerator : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::RotatedToken>> world_vectors_in;
  sc_core::sc_port<FifoWriteIf<cycle::AddressToken>> cube_addresses_out;

  SC_HAS_PROCESS(CubeFaceAddressGenerator);
  CubeFaceAddressGenerator(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::RotatedToken>* in_ = nullptr;
  FifoWriteIf<cycle::AddressToken>* out_ = nullptr;
};

}  // namespace arp::scm
