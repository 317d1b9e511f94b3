// Orientation matrix unit: loads the orientation register at latch points and rotates each view
// vector into the cube frame.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class OrientationMatrixUnit : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::LensToken>> view_vectors_in;
  sc_core::sc_port<FifoWriteIf<cycle::RotatedToken>> world_vectors_out;

  SC_HAS_PROCESS(OrientationMatrixUnit);
  OrientationMatrixUnit(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::LensToken>* in_ = nullptr;
  FifoWriteIf<cycle::RotatedToken>* out_ = nullptr;
};

}  // namespace arp::scm
