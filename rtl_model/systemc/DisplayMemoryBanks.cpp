#include "DisplayMemoryBanks.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

DisplayMemoryBanks::DisplayMemoryBanks(sc_module_name name, const stage::StageContext& ctx)
    : StageModule(name, ctx, kInput, kOutput, {"word_tap0_mem0", "weight_x", "weight_y"}),
      host_clk("host_clk"),
      host_(ctx.config(), ctx.in.host_jobs, *ctx.in.memories) {
  stage_.connect(&host_);
  SC_METHOD(on_host_clock);
  sensitive << host_clk;
  dont_initialize();
}

void DisplayMemoryBanks::trace_more(sc_trace_file* tf, const std::string& n) const {
  sc_trace(tf, stage_.swapper().front_select, n + ".front_select");
  sc_trace(tf, stage_.swapper().swap_strobe, n + ".swap_strobe");
  sc_trace(tf, host_.busy, n + ".host_busy");
  sc_trace(tf, host_.job, n + ".host_job");
  sc_trace(tf, host_.texels_written, n + ".host_texels_written");
}

}  // namespace arp::scm
