// The detailed cycle-accurate model: one SC_MODULE per stage, each owning its
// stage (rtl_model/stages) and run at each rising edge of the pixel clock by
// the clock generator (StageModule), linked by clocked FIFO channels named
// for what they carry. The host write port runs on the host clock. The top
// level only creates and binds: the stages are a list (ArpStages), from which
// StageChain makes the modules, the FIFOs between them and the schedule.
//
//   VideoTimingGenerator -pixel_requests-> LensVectorTable -view_vectors->
//   OrientationMatrixUnit (TrackerInterface: orientation register)
//   -world_vectors-> CubeFaceAddressGenerator -cube_addresses->
//   DisplayMemoryBanks -texel_words-> CompositionUnit -composed_taps->
//   AntiAliasingFilter -pixel_colors-> HmdScanOut
#pragma once
#include <systemc>

#include <array>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "AntiAliasingFilter.hpp"
#include "ClockGenerator.hpp"
#include "CompositionUnit.hpp"
#include "CubeFaceAddressGenerator.hpp"
#include "DisplayMemoryBanks.hpp"
#include "HmdScanOut.hpp"
#include "LensVectorTable.hpp"
#include "OrientationMatrixUnit.hpp"
#include "StageChain.hpp"
#include "TrackerInterface.hpp"
#include "VideoTimingGenerator.hpp"

namespace arp::scm {

// The ARP's pixel path, in data-flow order: the one list of its stages.
using ArpStages = StageList<VideoTimingGenerator, LensVectorTable, OrientationMatrixUnit, CubeFaceAddressGenerator,
                            DisplayMemoryBanks, CompositionUnit, AntiAliasingFilter, HmdScanOut>;

// Simulated time 0 is absolute time base_ps; the run ends at end_ps.
struct RunWindow {
  int64_t base_ps, end_ps;
  int64_t first_cycle, end_cycle;            // pixel clock
  int64_t first_host_cycle, end_host_cycle;  // host clock
};
RunWindow run_window(const stage::VideoTimingStage& timing, const dp::ArpConfig& c);

namespace detail {
// A stage of the configuration's list, with statistics.
template <class S, class = void>
struct configured_stage : std::false_type {};
template <class S>
struct configured_stage<S, std::void_t<decltype(std::declval<const S&>().stats())>> : std::bool_constant<(S::kInfo.id >= 0)> {};
}  // namespace detail

template <class List>
class DetailedPipeline : public sc_core::sc_module {
 public:
  // `clock_gating` off: both clocks tick every cycle, idle ones too (same results; to measure what gating saves).
  DetailedPipeline(sc_core::sc_module_name name, const stage::TimedInputs& in, bool clock_gating = true)
      : sc_core::sc_module(name),
        chain_(in),
        w_(run_window(timing().stage(), in.config)),
        pixel_clock("pixel_clock", in.config.timing.pixel_clock_hz, w_.base_ps, w_.first_cycle, w_.end_cycle),
        host_clock("host_clock", in.config.timed.host_clock_hz, w_.base_ps, w_.first_host_cycle, w_.end_host_cycle),
        tracker("tracker_interface", *in.orientation, w_.base_ps, w_.end_ps) {
    DisplayMemoryBanks& banks = chain_.template module<index_of<DisplayMemoryBanks>()>();
    // The pixel clock is gated while the pipeline is empty and nothing is due
    // (most of the blanking): those clocks would change nothing.
    if (clock_gating) {
      host_clock.gate([&banks](int64_t n) { return banks.host_port().next_active_cycle(n); });
      // Nor past the cycle a waveform opens before (trace_from): the window's idle clocks would be lost.
      pixel_clock.gate([this](int64_t n) {
        if (tracing_ || !idle()) return n;
        const int64_t busy = timing().stage().next_busy_cycle(n, w_.end_cycle);
        return n <= trace_cycle_ ? std::min(busy, trace_cycle_) : busy;
      });
    }
    chain_.bind_clock(pixel_clock);
    banks.host_clk(host_clock);
    chain_.for_each_fifo([this](auto& f) { f.start_statistics(w_.first_cycle); });
  }

  const RunWindow& window() const { return w_; }
  const stage::StageContext& context() const { return chain_.context(); }
  VideoTimingGenerator& timing() { return chain_.template module<0>(); }
  const VideoTimingGenerator& timing() const { return chain_.template module<0>(); }
  const HmdScanOut& scan_out() const { return chain_.template module<List::kSize - 1>(); }
  const DisplayMemoryBanks& memories() const { return chain_.template module<index_of<DisplayMemoryBanks>()>(); }
  const TrackerInterface& tracker_interface() const { return tracker; }
  int64_t evaluated_cycles() const { return pixel_clock.rising_edges(); }
  int64_t evaluated_host_cycles() const { return host_clock.rising_edges(); }
  StageChain<List>& chain() { return chain_; }

  // Waveforms: clocks, then every module (the tracker after the timing generator), then FIFO occupancy.
  void trace(sc_core::sc_trace_file* tf, bool data = true) {
    tracing_ = true;
    const std::string n = name();
    pixel_clock.trace(tf, n + ".pixel_clk");
    host_clock.trace(tf, n + ".host_clk");
    pixel_clock.trace_cycle(tf, n + ".pixel_cycle");
    chain_.for_each_module([&](auto& m) {
      m.trace(tf, data);
      if constexpr (std::is_same_v<std::decay_t<decltype(m)>, VideoTimingGenerator>) tracker.trace(tf);
    });
    chain_.for_each_fifo([&](const auto& f) { sc_trace(tf, f.occupancy_ref(), n + "." + f.name() + ".occupancy"); });
  }
  // Before the simulation starts, for a waveform that opens later, at absolute time abs_ps: clock gating does
  // not skip past the cycle that starts there (its edge runs at that instant, just before the waveform opens),
  // so the window shows its idle pixel clocks as it shows any others. (The host clock stays gated while its
  // port is idle, traced or not.)
  void trace_from(int64_t abs_ps) {
    trace_cycle_ = abs_ps == INT64_MAX ? INT64_MAX : dp::clock_cycle_at_or_after(abs_ps, chain_.context().config().timing.pixel_clock_hz);
  }
  void stop_tracing() {
    tracing_ = false;
    pixel_clock.stop_trace();
    host_clock.stop_trace();
    chain_.for_each_module([](auto& m) { m.stop_trace(); });
  }

  std::vector<std::pair<std::string, stage::FifoStats>> fifo_stats(int64_t end_cycle) const {
    std::vector<std::pair<std::string, stage::FifoStats>> s;
    chain_.for_each_fifo([&](const auto& f) { s.push_back({f.name(), f.stats(end_cycle)}); });
    return s;
  }
  // The configured stages' statistics, by dp::Stage (scan-out: its fixed latency).
  std::array<stage::StageStats, dp::kStageCount> stage_stats() const {
    std::array<stage::StageStats, dp::kStageCount> s{};
    chain_.for_each_module([&](const auto& m) {
      using S = typename std::decay_t<decltype(m)>::Stage;
      if constexpr (detail::configured_stage<S>::value) s[static_cast<size_t>(S::kInfo.id)] = m.stage().stats();
    });
    auto& so = s[static_cast<size_t>(dp::Stage::ScanOut)];
    so.latency_cycles = scan_out().stage().latency();
    so.min_cycles = so.max_cycles = so.latency_cycles;
    so.mean_cycles = so.latency_cycles;
    return s;
  }

 private:
  template <class M, size_t I = 0>
  static constexpr size_t index_of() {
    if constexpr (std::is_same_v<typename List::template Module<I>, M>) return I;
    else return index_of<M, I + 1>();
  }
  bool idle() const {
    bool empty = true;
    chain_.for_each_fifo([&](const auto& f) { empty = empty && f.occupancy() == 0; });
    chain_.for_each_module([&](const auto& m) { empty = empty && m.stage().idle(); });
    return empty;
  }

  StageChain<List> chain_;
  RunWindow w_;
  bool tracing_ = false;
  int64_t trace_cycle_ = INT64_MAX;  // the first pixel cycle after the waveform opens (trace_from)
  ClockGenerator pixel_clock, host_clock;
  TrackerInterface tracker;
};

using ArpPipelineTop = DetailedPipeline<ArpStages>;

}  // namespace arp::scm
