// Lens vector table: the ROM of head-frame viewing directions, read for each issued pixel.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class LensVectorTable : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_port<FifoReadIf<cycle::PixelSlot>> pixel_requests_in;
  sc_core::sc_port<FifoWriteIf<cycle::LensToken>> view_vectors_out;

  SC_HAS_PROCESS(LensVectorTable);
  LensVectorTable(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  FifoReadIf<cycle::PixelSlot>* in_ = nullptr;
  FifoWriteIf<cycle::LensToken>* out_ = nullptr;
};

}  // namespace arp::scm
