// What every pipeline stage module between two FIFOs has in common: a port
// to the clock, a port to the FIFO it reads and one to the FIFO it writes
// (SystemC names for what they carry), the stage object it owns (its
// registers, state and arithmetic: rtl_model/stages), one process on the
// rising clock edge running the stage's tick, and the waveform of its
// handshake and data. Each stage (LensVectorTable, OrientationMatrixUnit,
// ...) is its own module deriving from this, with its ports under their own
// names; any one can be instantiated alone (testbench/systemc/ModuleBenches).
#pragma once
#include <systemc>

#include <array>
#include <string>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

template <class S>
class StageModule : public sc_core::sc_module {
 public:
  using Stage = S;
  using Input = typename S::Input;
  using Output = typename S::Output;

  sc_core::sc_port<ClockIf> clk;
  sc_core::sc_port<FifoReadIf<Input>> input;
  sc_core::sc_port<FifoWriteIf<Output>> output;

  S& stage() { return stage_; }
  const S& stage() const { return stage_; }
  // Its place in the pipeline's schedule (a configured stage: its latency from the configuration).
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) {
    return {c.timed.stage[static_cast<size_t>(S::kId)].latency_cycles, static_cast<int>(S::kId)};
  }

  // Handshake (ready_in, valid_out) and the three data probes, then the stage's own signals.
  void trace(sc_core::sc_trace_file* tf) {
    stage_.set_probing(true);
    const std::string n = name();
    const auto& r = stage_.registers();
    sc_trace(tf, r.ready_in, n + ".ready_in");
    sc_trace(tf, r.valid_out, n + ".valid_out");
    for (size_t i = 0; i < 3; ++i) sc_trace(tf, r.data_out[i], n + "." + probes_[i]);
    trace_more(tf, n);
  }
  void stop_trace() { stage_.set_probing(false); }

 protected:
  SC_HAS_PROCESS(StageModule);
  // Ports named for what they carry: "<carries_in>_in", "<carries_out>_out";
  // probes: what the waveform's data_out[0..2] hold.
  StageModule(sc_core::sc_module_name name, const stage::StageContext& ctx, const char* carries_in, const char* carries_out,
              const std::array<const char*, 3>& probes)
      : sc_core::sc_module(name),
        clk("clk"),
        input((std::string(carries_in) + "_in").c_str()),
        output((std::string(carries_out) + "_out").c_str()),
        stage_(ctx),
        probes_(probes) {
    SC_METHOD(on_clock);
    sensitive << clk;
    dont_initialize();
  }
  virtual void trace_more(sc_core::sc_trace_file*, const std::string&) const {}

  S stage_;

 private:
  void on_clock() { stage_.tick(clk->cycle(), *in_, *out_); }
  void end_of_elaboration() override {
    in_ = input.operator->();
    out_ = output.operator->();
  }
  std::array<const char*, 3> probes_;
  FifoReadIf<Input>* in_ = nullptr;
  FifoWriteIf<Output>* out_ = nullptr;
};

}  // namespace arp::scm
