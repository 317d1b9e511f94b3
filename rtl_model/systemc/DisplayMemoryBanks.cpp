#include "DisplayMemoryBanks.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

DisplayMemoryBanks::DisplayMemoryBanks(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle, const int64_t& host_cycle)
    : sc_module(name), clk("clk"), host_clk("host_clk"), cube_addresses_in("cube_addresses_in"), texel_words_out("texel_words_out"), k_(k), cycle_(cycle), host_cycle_(host_cycle) {
  SC_METHOD(on_clock);
  sensitive << clk.pos();
  dont_initialize();
  SC_METHOD(on_host_clock);
  sensitive << host_clk.pos();
  dont_initialize();
}

void DisplayMemoryBanks::end_of_elaboration() {
  in_ = cube_addresses_in.operator->();
  out_ = texel_words_out.operator->();
}

void DisplayMemoryBanks::on_clock() { k_.tick_fetch(cycle_, *in_, *out_); }

void DisplayMemoryBanks::on_host_clock() { k_.tick_host(host_cycle_); }

void DisplayMemoryBanks::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, k_.fetch.ready_in, n + ".ready_in");
  sc_trace(tf, k_.fetch.valid_out, n + ".valid_out");
  sc_trace(tf, k_.fetch.data_out[0], n + ".word_tap0_mem0");
  sc_trace(tf, k_.fetch.data_out[1], n + ".weight_x");
  sc_trace(tf, k_.fetch.data_out[2], n + ".weight_y");
  sc_trace(tf, k_.swapper.front_select, n + ".front_select");
  sc_trace(tf, k_.swapper.swap_strobe, n + ".swap_strobe");
  sc_trace(tf, k_.host.busy, n + ".host_busy");
  sc_trace(tf, k_.host.job, n + ".host_job");
  sc_trace(tf, k_.host.texels_written, n + ".host_texels_written");
}

}  // namespace arp::scm
