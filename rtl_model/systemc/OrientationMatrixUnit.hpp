// Orientation matrix unit: loads the orientation register at latch points and rotates each
// view vector into the cube frame.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class OrientationMatrixUnit : public PipelineStageModule<cycle::LensToken, cycle::RotatedToken> {
 public:
  sc_core::sc_port<FifoReadIf<cycle::LensToken>>& view_vectors_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::RotatedToken>>& world_vectors_out = output_;

  SC_HAS_PROCESS(OrientationMatrixUnit);
  OrientationMatrixUnit(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);

 private:
  void tick(FifoReadIf<cycle::LensToken>& in, FifoWriteIf<cycle::RotatedToken>& out) override { k_.tick_rotate(cycle_, in, out); }
  void trace_more(sc_core::sc_trace_file* tf, const std::string& n) const override;
};

}  // namespace arp::scm
