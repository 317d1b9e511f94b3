// Cube-face address generator: rotated direction to face, texel and sub-texel position.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class CubeFaceAddressGenerator : public PipelineStageModule<cycle::RotatedToken, cycle::AddressToken> {
 public:
  sc_core::sc_port<FifoReadIf<cycle::RotatedToken>>& world_vectors_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::AddressToken>>& cube_addresses_out = output_;

  SC_HAS_PROCESS(CubeFaceAddressGenerator);
  CubeFaceAddressGenerator(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);

 private:
  void tick(FifoReadIf<cycle::RotatedToken>& in, FifoWriteIf<cycle::AddressToken>& out) override { k_.tick_address(cycle_, in, out); }
};

}  // namespace arp::scm
