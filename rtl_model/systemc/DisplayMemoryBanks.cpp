#include "DisplayMemoryBanks.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

DisplayMemoryBanks::DisplayMemoryBanks(sc_module_name name, const stage::StageContext& ctx)
    : StageModule(name, ctx), host_clk("host_clk"), host_(ctx.config(), ctx.in.host_jobs, *ctx.in.memories) {
  stage_.connect(&host_);
  SC_METHOD(on_host_clock);
  sensitive << host_clk;
  dont_initialize();
}

void DisplayMemoryBanks::trace(sc_trace_file* tf, bool data) {
  StageModule::trace(tf, data);
  const std::string n = name();
  sc_trace(tf, host_.busy, n + ".host_busy");
  sc_trace(tf, host_.job, n + ".host_job");
  sc_trace(tf, host_.texels_written, n + ".host_texels_written");
}

}  // namespace arp::scm
