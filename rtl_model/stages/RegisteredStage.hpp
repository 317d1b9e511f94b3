// What every stage between two FIFOs has: its register stages (StagePipe:
// `latency` clocks from taking a pixel to the next stage seeing it, with
// backpressure), its injected stalls, its statistics and its waveform
// probes. A stage derives from this (CRTP), naming itself by its row of the
// StageInfo table, and adds its arithmetic, `compute(in, out)`, and its own state. tick()
// is tick_with() the stage's own compute; the fast level may pass another.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "StageContext.hpp"
#include "StageInfo.hpp"
#include "StagePipe.hpp"

namespace arp::stage {

template <class Derived, class In, class Out, const StageInfo& Info>
class RegisteredStage {
 public:
  using Input = In;
  using Output = Out;
  static constexpr const StageInfo& kInfo = Info;

  int latency() const { return pipe_.latency(); }
  bool idle() const { return pipe_.occupancy() == 0; }
  StageStats stats() const { return pipe_.stats(); }
  void set_probing(bool on) { pipe_.probe_data = on; }
  // Its place in a pipeline's schedule: a configured stage's latency and id.
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) {
    return {c.timed.stage[static_cast<size_t>(Info.id)].latency_cycles, Info.id};
  }

  template <class InFifo, class OutFifo>
  void tick(int64_t cycle, InFifo& in, OutFifo& out) {
    derived().tick_with(cycle, in, out, [this](const In& t, Out& o) { derived().compute(t, o); });
  }
  // One clock with a given arithmetic.
  template <class InFifo, class OutFifo, class Fn>
  void tick_with(int64_t cycle, InFifo& in, OutFifo& out, Fn&& compute) {
    pipe_.tick(cycle, in, out, compute, stalled(cycle));
  }

  // The waveform: fn(name, value) for the handshake, the three data probes, then the stage's own.
  template <class Fn>
  void for_each_probe(Fn&& fn) const {
    fn("ready_in", pipe_.ready_in);
    fn("valid_out", pipe_.valid_out);
    static const std::array<ProbeFormat, 3> formats = probe_formats<Out>();
    for (size_t i = 0; i < 3; ++i) fn(Info.probes[i], NarrowProbe{pipe_.data_out[i], formats[i]});
    derived().for_each_own_probe(fn);
  }
  template <class Fn>
  void for_each_own_probe(Fn&&) const {}

 protected:
  // A configured stage: its latency and stalls from the context.
  explicit RegisteredStage(const StageContext& ctx)
      : pipe_(ctx.config().timed.stage[static_cast<size_t>(Info.id)].latency_cycles) {
    for (const auto& w : ctx.in.stalls)
      if (w.stage == Info.stage()) stalls_.push_back(w);
  }
  // A stage the configuration does not know (e.g. an inserted register).
  explicit RegisteredStage(int latency) : pipe_(latency) {}

 private:
  Derived& derived() { return static_cast<Derived&>(*this); }
  const Derived& derived() const { return static_cast<const Derived&>(*this); }
  bool stalled(int64_t c) const {
    for (const auto& w : stalls_)
      if (c >= w.first_cycle && c < w.first_cycle + w.cycles) return true;
    return false;
  }
  StagePipe<Out> pipe_;
  std::vector<StallWindow> stalls_;
};

}  // namespace arp::stage
