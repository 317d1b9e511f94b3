// A pipeline stage as a SystemC module: a port to the clock, a port to the
// FIFO it reads and one to the FIFO it writes (named for what they carry:
// <input>_in, <output>_out from its StageInfo; the first stage has no input, the last no
// output), the stage object it owns (its registers, state and arithmetic:
// rtl_model/stages), its activation on the rising clock edge running the stage's
// tick, and its waveform (the stage's probes). Any stage module can be
// instantiated alone (testbench/systemc/ModuleBenches).
//
// The activation: bound to a ClockGenerator, the module is run by the
// generator's own process at each rising edge (ClockGenerator::attach), as
// the stages of a clock domain are evaluated in one pass by a cycle-based
// simulator; bound to any other clock channel, it is a method process of its
// own, statically sensitive to the clock's rising edge. Either way it runs in
// the edge's evaluation phase and talks to the other stages only through its
// ports, so the two give the same cycles (the filter's bench runs both).
#pragma once
#include <systemc>
#include <sysc/kernel/sc_dynamic_processes.h>

#include <string>
#include <type_traits>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

// A stage's probe into a waveform: a value with its type's bits, a narrow
// probe (a register's data field) with its own.
template <class T>
void trace_probe(sc_core::sc_trace_file* tf, const T& value, const std::string& name) {
  sc_trace(tf, value, name);
}
inline void trace_probe(sc_core::sc_trace_file* tf, const stage::NarrowProbe& p, const std::string& name) {
  if (p.format.is_signed) {
    sc_trace(tf, p.value, name, p.format.bits);
  } else {  // the same 64 bits read unsigned (signed and unsigned variants may alias)
    sc_trace(tf, reinterpret_cast<const uint64_t&>(p.value), name, p.format.bits);
  }
}

// A stage's probes under `prefix` ("top.module."). Without `data`, its
// register's data fields are left out (the control signals stay: handshakes,
// scan position, the orientation register, the buffer select), and the stage
// does not compute them.
template <class S>
void trace_stage(sc_core::sc_trace_file* tf, S& stage, const std::string& prefix, bool data) {
  bool has_data = false;
  stage.for_each_probe([&](const std::string& probe, const auto& value) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, stage::NarrowProbe>) {
      has_data = true;
      if (!data) return;
    }
    trace_probe(tf, value, prefix + probe);
  });
  stage.set_probing(data || !has_data);
}

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
class StageModule : public sc_core::sc_module, private RisingEdgeCallee {
 public:
  using Stage = S;
  using Input = typename S::Input;
  using Output = typename S::Output;
  static constexpr const char* kInstance = S::kInfo.block;
  static constexpr const char* kOutput = S::kInfo.output;

  sc_core::sc_port<ClockIf> clk;
  detail::InPort<Input> input;
  detail::OutPort<Output> output;

  StageModule(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : sc_core::sc_module(name),
        clk("clk"),
        input(detail::port_name(S::kInfo.input, "_in").c_str()),
        output(detail::port_name(S::kInfo.output, "_out").c_str()),
        stage_(ctx) {}

  S& stage() { return stage_; }
  const S& stage() const { return stage_; }
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) { return S::scheduled(c); }

  // data: the register's data fields too (VcdOptions::data).
  void trace(sc_core::sc_trace_file* tf, bool data = true) { trace_stage(tf, stage_, std::string(name()) + ".", data); }
  void stop_trace() { stage_.set_probing(false); }
  // After elaboration: whether its clock port is bound to a ClockGenerator, which runs it and whose
  // cycle it reads directly.
  bool reads_clock_directly() const { return clock_ != nullptr; }

 protected:
  S stage_;

 private:
  // Ports bound to FifoChannels (every pipeline's and bench's) are called
  // directly, the FIFO's operations inlined into the stage's tick; any other
  // channel with the interfaces goes through their virtual functions. So is
  // a clock port bound to a ClockGenerator.
  void on_clock() {
    const int64_t cycle = clock_ ? clock_->cycle() : clk->cycle();
    if constexpr (std::is_void_v<Input>) {
      if (out_fifo_) stage_.tick(cycle, *out_fifo_);
      else stage_.tick(cycle, *out_);
    } else if constexpr (std::is_void_v<Output>) {
      if (in_fifo_) stage_.tick(cycle, *in_fifo_);
      else stage_.tick(cycle, *in_);
    } else {
      if (in_fifo_ && out_fifo_) stage_.tick(cycle, *in_fifo_, *out_fifo_);
      else stage_.tick(cycle, *in_, *out_);
    }
  }
  void on_rising_edge() override { on_clock(); }
  void end_of_elaboration() override {
    if (ClockGenerator* gen = dynamic_cast<ClockGenerator*>(clk.operator->())) {
      clock_ = gen;
      gen->attach(*this);
    } else {
      sc_core::sc_spawn_options opt;
      opt.spawn_method();
      opt.dont_initialize();
      opt.set_sensitivity(&clk->posedge_event());
      sc_core::sc_spawn([this] { on_clock(); }, "on_clock", &opt);
    }
    if constexpr (!std::is_void_v<Input>) {
      in_ = input.operator->();
      in_fifo_ = dynamic_cast<FifoChannel<Input>*>(in_);
    }
    if constexpr (!std::is_void_v<Output>) {
      out_ = output.operator->();
      out_fifo_ = dynamic_cast<FifoChannel<Output>*>(out_);
    }
  }
  template <template <class> class C, class T>
  using Ptr = std::conditional_t<std::is_void_v<T>, void*, C<T>*>;  // (no input or output: unused)
  const ClockGenerator* clock_ = nullptr;
  Ptr<FifoReadIf, Input> in_ = nullptr;
  Ptr<FifoWriteIf, Output> out_ = nullptr;
  Ptr<FifoChannel, Input> in_fifo_ = nullptr;
  Ptr<FifoChannel, Output> out_fifo_ = nullptr;
};

}  // namespace arp::scm
