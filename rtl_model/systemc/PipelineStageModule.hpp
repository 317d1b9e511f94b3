// What every pipeline stage module between two FIFOs has in common: a clock
// input, a port to the FIFO it reads and one to the FIFO it writes (with
// SystemC names for what they carry), one process on the rising clock edge
// running the stage's kernel tick, and the waveform of its handshake and data.
// Each stage (LensVectorTable, OrientationMatrixUnit, ...) is its own module
// deriving from this, with its ports under their own names.
#pragma once
#include <systemc>

#include <array>
#include <string>

#include "FifoChannel.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

template <class In, class Out>
class PipelineStageModule : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;

  // Handshake (ready_in, valid_out) and the three data probes, then the stage's own signals.
  void trace(sc_core::sc_trace_file* tf) const {
    const std::string n = name();
    sc_trace(tf, pipe_.ready_in, n + ".ready_in");
    sc_trace(tf, pipe_.valid_out, n + ".valid_out");
    for (size_t i = 0; i < 3; ++i) sc_trace(tf, pipe_.data_out[i], n + "." + probes_[i]);
    trace_more(tf, n);
  }

 protected:
  struct Names {
    const char* input;
    const char* output;
    std::array<const char*, 3> probes;  // what data_out[0..2] hold
  };

  SC_HAS_PROCESS(PipelineStageModule);
  PipelineStageModule(sc_core::sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle,
                      const cycle::StagePipe<Out>& pipe, const Names& names)
      : sc_core::sc_module(name),
        clk("clk"),
        input_(names.input),
        output_(names.output),
        k_(k),
        cycle_(cycle),
        pipe_(pipe),
        probes_(names.probes) {
    SC_METHOD(on_clock);
    sensitive << clk.pos();
    dont_initialize();
  }

  // One rising edge of the stage: its kernel tick on the two FIFOs.
  virtual void tick(FifoReadIf<In>& in, FifoWriteIf<Out>& out) = 0;
  virtual void trace_more(sc_core::sc_trace_file*, const std::string&) const {}

  sc_core::sc_port<FifoReadIf<In>> input_;
  sc_core::sc_port<FifoWriteIf<Out>> output_;
  cycle::PipelineKernels& k_;
  const int64_t& cycle_;

 private:
  void on_clock() { tick(*in_, *out_); }
  void end_of_elaboration() override {
    in_ = input_.operator->();
    out_ = output_.operator->();
  }
  const cycle::StagePipe<Out>& pipe_;
  std::array<const char*, 3> probes_;
  FifoReadIf<In>* in_ = nullptr;
  FifoWriteIf<Out>* out_ = nullptr;
};

}  // namespace arp::scm
