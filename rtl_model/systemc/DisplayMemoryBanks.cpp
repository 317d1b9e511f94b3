#include "DisplayMemoryBanks.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

DisplayMemoryBanks::DisplayMemoryBanks(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle, const int64_t& host_cycle)
    : PipelineStageModule(name, k, cycle, k.fetch, {"cube_addresses_in", "texel_words_out", {"word_tap0_mem0", "weight_x", "weight_y"}}),
      host_clk("host_clk"),
      host_cycle_(host_cycle) {
  SC_METHOD(on_host_clock);
  sensitive << host_clk.pos();
  dont_initialize();
}

void DisplayMemoryBanks::on_host_clock() { k_.tick_host(host_cycle_); }

void DisplayMemoryBanks::trace_more(sc_trace_file* tf, const std::string& n) const {
  sc_trace(tf, k_.swapper.front_select, n + ".front_select");
  sc_trace(tf, k_.swapper.swap_strobe, n + ".swap_strobe");
  sc_trace(tf, k_.host.busy, n + ".host_busy");
  sc_trace(tf, k_.host.job, n + ".host_job");
  sc_trace(tf, k_.host.texels_written, n + ".host_texels_written");
}

}  // namespace arp::scm
