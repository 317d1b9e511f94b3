// The fast cycle-accurate model: one process per clock domain. The pixel
// clock's process ticks the same stage objects as the detailed model's
// modules (the same StageList: rtl_model/stages) on plain FIFO cores, then
// clocks the FIFOs -- the same cycle semantics, without a signal or a
// process per stage. The host clock's process ticks the host write port.
// Three exact shortcuts, all off while a waveform is traced:
// - frame speculation (FrameSpeculation), which wraps the stages' arithmetic;
// - temporal decoupling: one activation evaluates up to kBatch cycles ahead
//   of simulated time, stopping before each vertical-blank swap cycle -- the
//   only cycle that reads another domain's state (the host's commits);
// - when the pipeline is empty and nothing is due (blanking) it jumps to the
//   next cycle where something is.
#pragma once
#include <systemc>

#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ArpPipelineTop.hpp"
#include "FrameSpeculation.hpp"
#include "TrackerInterface.hpp"
#include "rtl_model/stages/ClockedFifo.hpp"

namespace arp::scm {

class FastCycleModel : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(FastCycleModel);
  // `clock_gating` off: every pixel and host clock evaluated, idle ones too (same results; to measure what gating saves).
  FastCycleModel(sc_core::sc_module_name name, const stage::TimedInputs& in, bool speculate, bool clock_gating = true);

  const RunWindow& window() const { return w_; }
  void trace(sc_core::sc_trace_file* tf, bool data = true);
  void stop_tracing();
  // Before the simulation starts, for a waveform that opens later, at absolute time abs_ps: the evaluation
  // does not run ahead past it (neither a batch nor a jump over idle cycles), so the first cycle after it is
  // evaluated with the waveform open, as the detailed level's clock edges are.
  void trace_from(int64_t abs_ps);
  const TrackerInterface& tracker_interface() const { return tracker; }
  std::vector<std::pair<std::string, stage::FifoStats>> fifo_stats(int64_t end_cycle) const;
  std::array<stage::StageStats, dp::kStageCount> stage_stats() const;
  const stage::VideoTimingStage& timing() const { return std::get<0>(stages_); }
  const stage::ScanOutStage& scan_out() const { return std::get<ArpStages::kSize - 1>(stages_); }
  const stage::MemoryReadStage& memories() const { return std::get<stage::MemoryReadStage>(stages_); }
  const stage::HostWritePort& host_port() const { return host_; }
  const FrameSpeculation* speculation() const { return spec_.get(); }
  int64_t evaluated_cycles() const { return evaluated_; }
  int64_t evaluated_host_cycles() const { return host_evaluated_; }

 private:
  template <class... M>
  static auto stage_tuple(std::tuple<M...>*) -> std::tuple<typename M::Stage...>;
  using Stages = decltype(stage_tuple(static_cast<ArpStages::Modules*>(nullptr)));
  static constexpr size_t kN = ArpStages::kSize;

  void pixel_domain();
  void host_domain();
  bool idle() const;
  void evaluate(int64_t c);
  template <size_t... I>
  void tick_middle(int64_t c, std::index_sequence<I...>);
  template <class S, class I, class O>
  void tick_stage(S& s, int64_t c, I& in, O& out) {
    if (spec_) spec_->tick(s, c, in, out);
    else s.tick(c, in, out);
  }
  static constexpr int64_t kBatch = 4096;

  stage::StageContext ctx_;
  Stages stages_;
  stage::HostWritePort host_;
  ArpStages::FifoValues<stage::ClockedFifo> fifos_;
  RunWindow w_;
  int64_t pixel_hz_, host_hz_;
  TrackerInterface tracker;
  std::unique_ptr<FrameSpeculation> spec_;
  int64_t cycle_, host_cycle_;
  int64_t trace_cycle_ = INT64_MAX;  // the first pixel cycle after the waveform opens (trace_from)
  int64_t evaluated_ = 0, host_evaluated_ = 0;
  bool tracing_ = false, started_ = false, host_started_ = false;
  bool gating_ = true;
};

}  // namespace arp::scm
