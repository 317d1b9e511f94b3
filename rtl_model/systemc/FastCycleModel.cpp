#include "FastCycleModel.hpp"

#include <algorithm>

#include "ClockGenerator.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::scm {

using namespace sc_core;

namespace {
template <class Stages, size_t... I>
Stages make_stages(const stage::StageContext& ctx, std::index_sequence<I...>) {
  return Stages((static_cast<void>(I), ctx)...);
}
}  // namespace

FastCycleModel::FastCycleModel(sc_module_name name, const stage::TimedInputs& in, bool speculate, bool clock_gating)
    : sc_module(name),
      ctx_{in, ArpStages::schedule(in.config)},
      stages_(make_stages<Stages>(ctx_, std::make_index_sequence<kN>{})),
      host_(in.config, in.host_jobs, *in.memories),
      fifos_(ArpStages::make_fifo_values<stage::ClockedFifo>(in.config.timed.fifo_depth, std::make_index_sequence<kN - 1>{})),
      w_(run_window(timing(), in.config)),
      pixel_hz_(in.config.timing.pixel_clock_hz),
      host_hz_(in.config.timed.host_clock_hz),
      tracker("tracker_interface", *in.orientation, w_.base_ps, w_.end_ps),
      cycle_(w_.first_cycle),
      host_cycle_(w_.first_host_cycle),
      gating_(clock_gating) {
  std::get<stage::MemoryReadStage>(stages_).connect(&host_);
  std::apply([this](auto&... f) { (f.start_statistics(w_.first_cycle), ...); }, fifos_);
  if (speculate) {
    spec_ = std::make_unique<FrameSpeculation>(ctx_, std::get<stage::LensVectorStage>(stages_),
                                               std::get<stage::OrientationStage>(stages_),
                                               std::get<stage::AddressStage>(stages_), memories());
    std::get<stage::ScanOutStage>(stages_).use_prerendered(spec_.get());
  }
  SC_METHOD(pixel_domain);
  SC_METHOD(host_domain);
}

bool FastCycleModel::idle() const {
  return std::apply([](const auto&... f) { return ((f.occupancy() == 0) && ...); }, fifos_) &&
         std::apply([](const auto&... s) { return (s.idle() && ...); }, stages_);
}

template <size_t... I>
void FastCycleModel::tick_middle(int64_t c, std::index_sequence<I...>) {
  (tick_stage(std::get<I + 1>(stages_), c, std::get<I>(fifos_), std::get<I + 1>(fifos_)), ...);
}

// One pixel clock: every stage in data-flow order, then the clock edge of every FIFO.
void FastCycleModel::evaluate(int64_t c) {
  std::get<0>(stages_).tick(c, std::get<0>(fifos_));
  tick_middle(c, std::make_index_sequence<kN - 2>{});
  std::get<kN - 1>(stages_).tick(c, std::get<kN - 2>(fifos_));
  std::apply([](auto&... f) { (f.update(), ...); }, fifos_);
  ++evaluated_;
}

void FastCycleModel::pixel_domain() {
  const sc_time now = sc_time_stamp();
  if (!started_) {
    started_ = true;
    next_trigger(sim_time(dp::clock_cycle_to_ps(cycle_, pixel_hz_), w_.base_ps) - now);
    return;
  }
  const auto& sched = ctx_.schedule;
  const int64_t F = timing().scan().timing().frame_cycles();
  // Never run past a swap cycle: it must be evaluated at its own time.
  const int64_t f = (cycle_ - sched.swap_cycle(0)) / F;
  int64_t stop = w_.end_cycle;
  for (int64_t g = f - 1; g <= f + 2; ++g)
    if (sched.swap_cycle(g) > cycle_) stop = std::min(stop, sched.swap_cycle(g));
  // Nor past the cycle a waveform opens before (trace_from): it would start after cycles it should show.
  const int64_t hold = !tracing_ && trace_cycle_ > cycle_ ? trace_cycle_ : w_.end_cycle;
  if (tracing_) stop = cycle_ + 1;
  else stop = std::min({stop, cycle_ + kBatch, hold});
  int64_t c = cycle_;
  while (c < stop) {
    evaluate(c++);
    if (gating_ && !tracing_ && c < stop && idle()) c = std::min(stop, timing().next_busy_cycle(c, w_.end_cycle));
  }
  cycle_ = c;
  if (gating_ && !tracing_ && idle()) cycle_ = std::min(hold, timing().next_busy_cycle(cycle_, w_.end_cycle));
  if (cycle_ < w_.end_cycle) next_trigger(sim_time(dp::clock_cycle_to_ps(cycle_, pixel_hz_), w_.base_ps) - now);
}

void FastCycleModel::host_domain() {
  const sc_time now = sc_time_stamp();
  if (host_started_) {
    host_.tick(host_cycle_);
    ++host_cycle_;
    ++host_evaluated_;
  }
  host_started_ = true;
  if (gating_) host_cycle_ = host_.next_active_cycle(host_cycle_);  // gated while the port is idle
  if (host_cycle_ < w_.end_host_cycle)
    next_trigger(sim_time(dp::clock_cycle_to_ps(host_cycle_, host_hz_), w_.base_ps) - now);
}

// The same signals as the detailed model's modules (each stage's probes under its module's name).
void FastCycleModel::trace(sc_trace_file* tf, bool data) {
  tracing_ = true;
  const std::string n = name();
  sc_trace(tf, cycle_, n + ".pixel_cycle");
  std::apply(
      [&](auto&... st) {
        auto one = [&](auto& s) {
          trace_stage(tf, s, n + "." + std::decay_t<decltype(s)>::kInfo.block + ".", data);
          if constexpr (std::is_same_v<std::decay_t<decltype(s)>, stage::VideoTimingStage>) tracker.trace(tf);
        };
        (one(st), ...);
      },
      stages_);
  sc_trace(tf, host_.busy, n + ".display_memory_banks.host_busy");
  std::apply([&](const auto&... f) { (sc_trace(tf, f.occupancy_ref(), n + "." + f.name() + ".occupancy"), ...); }, fifos_);
}

void FastCycleModel::trace_from(int64_t abs_ps) {
  // The first cycle strictly after it: the kernel runs the activations at the window's own instant before the
  // waveform opens (sc_start runs to and including its end time), as it runs the detailed level's edges there.
  trace_cycle_ = abs_ps == INT64_MAX ? INT64_MAX : dp::clock_cycle_at_or_after(abs_ps + 1, pixel_hz_);
}

void FastCycleModel::stop_tracing() {
  tracing_ = false;
  std::apply([](auto&... s) { (s.set_probing(false), ...); }, stages_);
}

std::vector<std::pair<std::string, stage::FifoStats>> FastCycleModel::fifo_stats(int64_t end_cycle) const {
  std::vector<std::pair<std::string, stage::FifoStats>> s;
  std::apply([&](const auto&... f) { (s.push_back({f.name(), f.stats(end_cycle)}), ...); }, fifos_);
  return s;
}

std::array<stage::StageStats, dp::kStageCount> FastCycleModel::stage_stats() const {
  std::array<stage::StageStats, dp::kStageCount> s{};
  std::apply(
      [&](const auto&... st) {
        auto one = [&](const auto& x) {
          if constexpr (detail::configured_stage<std::decay_t<decltype(x)>>::value)
            s[static_cast<size_t>(std::decay_t<decltype(x)>::kInfo.id)] = x.stats();
        };
        (one(st), ...);
      },
      stages_);
  auto& so = s[static_cast<size_t>(dp::Stage::ScanOut)];
  so.latency_cycles = scan_out().latency();
  so.min_cycles = so.max_cycles = so.latency_cycles;
  so.mean_cycles = so.latency_cycles;
  return s;
}

}  // namespace arp::scm
