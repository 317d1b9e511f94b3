// Display memory banks: the pipeline read port (every memory and tap in parallel) with the
// double-buffer swap at vertical blank on the pixel clock, and the host write port on the
// host clock.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include "PipelineStageModule.hpp"

namespace arp::scm {

class DisplayMemoryBanks : public PipelineStageModule<cycle::AddressToken, cycle::FetchToken> {
 public:
  sc_core::sc_in<bool> host_clk;
  sc_core::sc_port<FifoReadIf<cycle::AddressToken>>& cube_addresses_in = input_;
  sc_core::sc_port<FifoWriteIf<cycle::FetchToken>>& texel_words_out = output_;

  SC_HAS_PROCESS(DisplayMemoryBanks);
  DisplayMemoryBanks(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle, const int64_t& host_cycle);

 private:
  void tick(FifoReadIf<cycle::AddressToken>& in, FifoWriteIf<cycle::FetchToken>& out) override { k_.tick_fetch(cycle_, in, out); }
  void on_host_clock();
  const int64_t& host_cycle_;
  void trace_more(sc_core::sc_trace_file* tf, const std::string& n) const override;
};

}  // namespace arp::scm
