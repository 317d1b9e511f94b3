// Display memory banks: the pipeline read port (every memory and tap in parallel) with the
// double-buffer swap at vertical blank on the pixel clock, and the host write port on the host
// clock.
// Its arithmetic is the datapath's, through cycle::PipelineKernels.
#pragma once
#include <systemc>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class DisplayMemoryBanks : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_in<bool> host_clk;
  sc_core::sc_port<FifoReadIf<cycle::AddressToken>> cube_addresses_in;
  sc_core::sc_port<FifoWriteIf<cycle::FetchToken>> texel_words_out;

  SC_HAS_PROCESS(DisplayMemoryBanks);
  DisplayMemoryBanks(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle, const int64_t& host_cycle);
  void trace(sc_core::sc_trace_file* tf) const;

 private:
  void end_of_elaboration() override;
  void on_clock();
  void on_host_clock();
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;
  const int64_t& host_cycle_;
  FifoReadIf<cycle::AddressToken>* in_ = nullptr;
  FifoWriteIf<cycle::FetchToken>* out_ = nullptr;
};

}  // namespace arp::scm
