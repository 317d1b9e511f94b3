// Lens vector table: the ROM of head-frame viewing directions, read for each issued pixel.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class LensVectorTable : public PipelineStageModule<cycle::PixelSlot, cycle::LensToken> {
 public:
  sc_core::sc_port<FifoReadIf<cycle::PixelSlot>>& pixel_requests_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::LensToken>>& view_vectors_out = output_;

  SC_HAS_PROCESS(LensVectorTable);
  LensVectorTable(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle);

 private:
  void tick(FifoReadIf<cycle::PixelSlot>& in, FifoWriteIf<cycle::LensToken>& out) override { k_.tick_lens(cycle_, in, out); }
};

}  // namespace arp::scm
