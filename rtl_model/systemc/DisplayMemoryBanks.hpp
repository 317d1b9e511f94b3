// Display memory banks: the pipeline read port (every memory and tap in
// parallel) with the double-buffer swap at vertical blank on the pixel clock
// (stage::MemoryReadStage), and the host write port on the host clock
// (stage::HostWritePort), both over the same memories.
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/HostWritePort.hpp"
#include "rtl_model/stages/MemoryReadStage.hpp"

namespace arp::scm {

class DisplayMemoryBanks : public StageModule<stage::MemoryReadStage> {
 public:
  sc_core::sc_port<ClockIf> host_clk;

  SC_HAS_PROCESS(DisplayMemoryBanks);
  DisplayMemoryBanks(sc_core::sc_module_name name, const stage::StageContext& ctx);

  const stage::HostWritePort& host_port() const { return host_; }
  // The read port's waveform, then the write port's.
  void trace(sc_core::sc_trace_file* tf, bool data = true);

 private:
  void on_host_clock() { host_.tick(host_clk->cycle()); }
  stage::HostWritePort host_;
};

}  // namespace arp::scm
