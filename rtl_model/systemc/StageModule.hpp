// A pipeline stage as a SystemC module: a port to the clock, a port to the
// FIFO it reads and one to the FIFO it writes (named for what they carry:
// <input>_in, <output>_out from its StageInfo; the first stage has no input, the last no
// output), the stage object it owns (its registers, state and arithmetic:
// rtl_model/stages), one process on the rising clock edge running the stage's
// tick, and its waveform (the stage's probes). Any stage module can be
// instantiated alone (testbench/systemc/ModuleBenches).
#pragma once
#include <systemc>

#include <string>
#include <type_traits>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

namespace detail {
struct NoPort {  // where a stage has no input (or no output)
  explicit NoPort(const char*) {}
};
template <class T>
using InPort = std::conditional_t<std::is_void_v<T>, NoPort, sc_core::sc_port<FifoReadIf<T>>>;
template <class T>
using OutPort = std::conditional_t<std::is_void_v<T>, NoPort, sc_core::sc_port<FifoWriteIf<T>>>;
inline std::string port_name(const char* carries, const char* suffix) { return carries ? carries + std::string(suffix) : "none"; }
}  // namespace detail

template <class S>
class StageModule : public sc_core::sc_module {
 public:
  using Stage = S;
  using Input = typename S::Input;
  using Output = typename S::Output;
  static constexpr const char* kInstance = S::kInfo.block;
  static constexpr const char* kOutput = S::kInfo.output;

  sc_core::sc_port<ClockIf> clk;
  detail::InPort<Input> input;
  detail::OutPort<Output> output;

  SC_HAS_PROCESS(StageModule);
  StageModule(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : sc_core::sc_module(name),
        clk("clk"),
        input(detail::port_name(S::kInfo.input, "_in").c_str()),
        output(detail::port_name(S::kInfo.output, "_out").c_str()),
        stage_(ctx) {
    SC_METHOD(on_clock);
    sensitive << clk;
    dont_initialize();
  }

  S& stage() { return stage_; }
  const S& stage() const { return stage_; }
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) { return S::scheduled(c); }

  void trace(sc_core::sc_trace_file* tf) {
    stage_.set_probing(true);
    const std::string n = name();
    stage_.for_each_probe([&](const std::string& probe, const auto& value) { sc_trace(tf, value, n + "." + probe); });
  }
  void stop_trace() { stage_.set_probing(false); }

 protected:
  S stage_;

 private:
  void on_clock() {
    if constexpr (std::is_void_v<Input>) stage_.tick(clk->cycle(), *out_);
    else if constexpr (std::is_void_v<Output>) stage_.tick(clk->cycle(), *in_);
    else stage_.tick(clk->cycle(), *in_, *out_);
  }
  void end_of_elaboration() override {
    if constexpr (!std::is_void_v<Input>) in_ = input.operator->();
    if constexpr (!std::is_void_v<Output>) out_ = output.operator->();
  }
  std::conditional_t<std::is_void_v<Input>, void*, FifoReadIf<Input>*> in_ = nullptr;
  std::conditional_t<std::is_void_v<Output>, void*, FifoWriteIf<Output>*> out_ = nullptr;
};

}  // namespace arp::scm
