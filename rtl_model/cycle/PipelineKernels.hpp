// Every stage's clocked behaviour, as plain C++ on any FIFO type. The
// detailed model calls one tick_* per SC_MODULE process with its channels;
// the fast model calls them all from one process per clock with plain FIFOs.
// Both therefore share one cycle semantics, and each tick only sees FIFO
// state from the start of the cycle, so evaluation order cannot matter.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <cstdint>
#include <vector>

#include "FrameReport.hpp"
#include "FrameSpeculation.hpp"
#include "HostWritePort.hpp"
#include "OrientationLatch.hpp"
#include "ScanOutStage.hpp"
#include "ScanTiming.hpp"
#include "StageArithmetic.hpp"
#include "StagePipe.hpp"

namespace arp::cycle {

// An injected stall: `stage` does nothing for `cycles` pixel clocks from `first_cycle`.
struct StallWindow {
  dp::Stage stage;
  int64_t first_cycle, cycles;
};

// One run's inputs, the same for every fidelity level.
struct TimedInputs {
  dp::ArpConfig config;
  dp::DisplayMemorySet* memories = nullptr;     // loaded front buffers; host jobs write the back buffers
  const dp::OrientationStream* orientation = nullptr;
  std::vector<HostWriteJob> host_jobs;
  int64_t first_frame = 0, frames = 1;
  std::vector<StallWindow> stalls;              // cycle-accurate levels only
  FrameSink sink;
  // A host model updating the memories between frames: called before each
  // frame (the frame, its start in seconds) -- at the functional level before
  // rendering it, at the timed levels at the start and then in the vertical
  // blank before it (the buffer-swap clock), when no pixel is in flight.
  std::function<void(int64_t, double)> before_frame;
};

class PipelineKernels {
 public:
  explicit PipelineKernels(const TimedInputs& in);

  StageArithmetic arith;
  ScanTiming scan;
  OrientationLatch latch;
  HostWritePort host;
  BufferSwapper swapper;
  StagePipe<LensToken> lens;
  StagePipe<RotatedToken> rotate;
  StagePipe<AddressToken> address;
  StagePipe<FetchToken> fetch;
  StagePipe<ComposedToken> compose;
  StagePipe<ColorToken> filter;
  ScanOutStage scanout;

  template <class O>
  void tick_timing(int64_t c, O& out) { scan.tick(c, out); }
  template <class I, class O>
  void tick_lens(int64_t c, I& in, O& out) {
    lens.tick(
        c, in, out,
        [this](const PixelSlot& s, LensToken& o) {
          if (spec_) o.slot = s;  // the view vectors are read only if the pixel leaves the schedule
          else arith.lens(s, o);
        },
        stalled(dp::Stage::Lens, c));
  }
  template <class I, class O>
  void tick_rotate(int64_t c, I& in, O& out) {
    rotate.tick(
        c, in, out,
        [this, c](const LensToken& t, RotatedToken& o) {
          latch.on_pixel(t.slot, c);
          if (spec_ && speculate_rotate(t, c, o)) return;
          if (spec_) {  // off the schedule: the view vectors were not read
            LensToken full;
            arith.lens(t.slot, full);
            arith.rotate(full, latch.matrix, latch.sample, o);
          } else {
            arith.rotate(t, latch.matrix, latch.sample, o);
          }
          o.slot.on_schedule = false;
        },
        stalled(dp::Stage::Rotate, c));
  }
  template <class I, class O>
  void tick_address(int64_t c, I& in, O& out) {
    address.tick(
        c, in, out,
        [this](const RotatedToken& t, AddressToken& o) {
          if (t.slot.on_schedule) {
            o.slot = t.slot;
            o.sample = t.sample;
          } else {
            arith.address(t, o);
          }
        },
        stalled(dp::Stage::Address, c));
  }
  // The memories' pipeline read port; the vertical-blank swap happens first in the same clock.
  template <class I, class O>
  void tick_fetch(int64_t c, I& in, O& out) {
    swapper.tick(c);
    fetch.tick(
        c, in, out,
        [this](const AddressToken& t, FetchToken& o) {
          if (t.slot.on_schedule) {
            if (spec_->swaps_at_render(t.slot.frame) == swapper.generation()) {
              o.slot = t.slot;
              o.sample = t.sample;
              o.memories = o.taps = 0;  // no words travel with it
              return;
            }
            recompute_address(t, o);  // a swap since the frame was rendered: fetch for real
            return;
          }
          arith.fetch(t, *mem_, o);
        },
        stalled(dp::Stage::Fetch, c));
  }
  template <class I, class O>
  void tick_compose(int64_t c, I& in, O& out) {
    compose.tick(
        c, in, out,
        [this](const FetchToken& t, ComposedToken& o) {
          if (t.slot.on_schedule) {
            o.slot = t.slot;
            o.sample = t.sample;
          } else {
            arith.compose(t, o);
          }
        },
        stalled(dp::Stage::Compose, c));
  }
  template <class I, class O>
  void tick_filter(int64_t c, I& in, O& out) {
    filter.tick(
        c, in, out,
        [this](const ComposedToken& t, ColorToken& o) {
          if (t.slot.on_schedule) {
            o.slot = t.slot;
            o.sample = t.sample;
          } else {
            arith.filter(t, o);
          }
        },
        stalled(dp::Stage::Filter, c));
  }
  template <class I>
  void tick_scanout(int64_t c, I& in) { scanout.tick(c, in); }
  void tick_host(int64_t host_cycle) { host.tick(host_cycle); }

  std::array<StageStats, dp::kStageCount> stage_stats() const;

  // Fast model only: evaluate frames ahead on the nominal schedule (see FrameSpeculation).
  void enable_speculation(bool on) {
    set_speculation(on);
    scanout.use_speculation(spec_.get());
  }
  const FrameSpeculation* speculation() const { return spec_.get(); }

  // Waveform tracing: the scan position and every stage's data are kept up to date.
  void set_tracing(bool on) {
    scan.track_position = on;
    lens.probe_data = rotate.probe_data = address.probe_data = on;
    fetch.probe_data = compose.probe_data = filter.probe_data = on;
  }

  // No pixel in any stage and none waiting to be issued (the FIFOs are the caller's to check).
  bool stages_idle() const {
    return scan.backlog == 0 && lens.occupancy() == 0 && rotate.occupancy() == 0 && address.occupancy() == 0 &&
           fetch.occupancy() == 0 && compose.occupancy() == 0 && filter.occupancy() == 0;
  }
  // With the whole pipeline idle: the first cycle at or after c (before `end`)
  // at which any stage can act -- an issue or a buffer swap. Models skip the
  // cycles in between; nothing observable happens in them (the skipped
  // cycles are still counted as simulated: they are the same clocks).
  int64_t next_busy_cycle(int64_t c, int64_t end) const;

 private:
  // On the schedule: the pixel keeps only its slot and sample; false: compute it.
  void set_speculation(bool on);
  bool speculate_rotate(const LensToken& t, int64_t c, RotatedToken& o);
  // An on-schedule pixel whose fetch crossed a swap: its address again, then the real fetch.
  void recompute_address(const AddressToken& t, FetchToken& o);
  bool stalled(dp::Stage s, int64_t c) const {
    if (!any_stalls_) return false;
    for (const auto& w : stalls_)
      if (w.stage == s && c >= w.first_cycle && c < w.first_cycle + w.cycles) return true;
    return false;
  }
  dp::DisplayMemorySet* mem_;
  std::vector<StallWindow> stalls_;
  bool any_stalls_;
  const dp::OrientationStream* orientation_;
  int64_t rotate_to_scanout_;
  std::unique_ptr<FrameSpeculation> spec_;
  bool register_on_schedule_ = false;
};

}  // namespace arp::cycle
