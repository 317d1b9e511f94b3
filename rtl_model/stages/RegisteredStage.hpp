// What every stage between two FIFOs has: its register stages (StagePipe:
// `latency` clocks from taking a pixel to the next stage seeing it, with
// backpressure), its injected stalls and its statistics. A stage derives from
// this and adds its arithmetic, `compute(in, out)`, and its own state; its
// tick() is tick_with() its own compute (the fast level may pass another).
#pragma once
#include <cstdint>
#include <vector>

#include "StageContext.hpp"
#include "StagePipe.hpp"

namespace arp::stage {

template <class In, class Out>
class RegisteredStage {
 public:
  using Input = In;
  using Output = Out;

  int latency() const { return pipe_.latency(); }
  bool idle() const { return pipe_.occupancy() == 0; }
  StageStats stats() const { return pipe_.stats(); }
  // Waveforms: the handshake and the last pixel's data (see probe() in PixelTokens.hpp).
  const StagePipe<Out>& registers() const { return pipe_; }
  void set_probing(bool on) { pipe_.probe_data = on; }

  // One clock with a given arithmetic (the stage's own, or a fast-level wrapper's).
  template <class InFifo, class OutFifo, class Fn>
  void tick_with(int64_t cycle, InFifo& in, OutFifo& out, Fn&& compute) {
    pipe_.tick(cycle, in, out, compute, stalled(cycle));
  }

 protected:
  // A configured stage: its latency and stalls from the context.
  RegisteredStage(const StageContext& ctx, dp::Stage id)
      : pipe_(ctx.config().timed.stage[static_cast<size_t>(id)].latency_cycles) {
    for (const auto& w : ctx.in.stalls)
      if (w.stage == id) stalls_.push_back(w);
  }
  // A stage the configuration does not know (e.g. an inserted register).
  explicit RegisteredStage(int latency) : pipe_(latency) {}

 private:
  bool stalled(int64_t c) const {
    for (const auto& w : stalls_)
      if (c >= w.first_cycle && c < w.first_cycle + w.cycles) return true;
    return false;
  }
  StagePipe<Out> pipe_;
  std::vector<StallWindow> stalls_;
};

}  // namespace arp::stage
