// The fast cycle-accurate level's shortcut, exact by construction and
// checked per pixel; a wrapper around the stages, used by the fast level
// only. A frame's pixels depend on the clock only through two things: which
// tracker sample the orientation register holds when a latch pixel enters
// the orientation matrix unit, and which buffers are in front when a pixel
// is fetched. On the nominal schedule (no stall) both are what the
// functional model assumes, so the fast level renders each frame once with
// the functional model's vectorised passes -- the same datapath arithmetic --
// and lets a pixel skip the stages' arithmetic (its tokens carry only slot
// and sample) while
//  - the register's sample is the one the nominal latch would read, and
//  - no buffer has swapped since the frame was rendered.
// Any other pixel (a stall moved a latch, a fetch crossed a swap) is
// computed stage by stage. The detailed level never speculates; waveform
// tracing turns it off too, so every stage shows its data.
#pragma once
#include <cstdint>
#include <map>
#include <memory>

#include "rtl_model/functional/FunctionalModel.hpp"
#include "rtl_model/stages/AddressStage.hpp"
#include "rtl_model/stages/LensVectorStage.hpp"
#include "rtl_model/stages/MemoryReadStage.hpp"
#include "rtl_model/stages/OrientationStage.hpp"
#include "rtl_model/stages/ScanOutStage.hpp"

namespace arp::scm {

class FrameSpeculation : public stage::PrerenderedFrames {
 public:
  FrameSpeculation(const stage::StageContext& ctx, const stage::LensVectorStage& lens, stage::OrientationStage& orientation,
                   const stage::AddressStage& address, const stage::MemoryReadStage& memories);

  // The lens vector table: the view vectors are read only if the pixel leaves the schedule.
  template <class I, class O>
  void tick(stage::LensVectorStage& s, int64_t c, I& in, O& out) {
    s.tick_with(c, in, out, [](const stage::PixelSlot& p, stage::LensToken& o) { o.slot = p; });
  }
  template <class I, class O>
  void tick(stage::OrientationStage& s, int64_t c, I& in, O& out) {
    s.tick_with(c, in, out, [this, c](const stage::LensToken& t, stage::RotatedToken& o) { rotate(t, c, o); });
  }
  template <class I, class O>
  void tick(stage::MemoryReadStage& s, int64_t c, I& in, O& out) {
    s.tick_with(c, in, out, [this](const stage::AddressToken& t, stage::FetchToken& o) { fetch(t, o); });
  }
  // Address, composition, filter: an on-schedule pixel passes with its slot
  // and sample; the rest are computed out of the hot loop.
  template <class S, class I, class O>
  void tick(S& s, int64_t c, I& in, O& out) {
    s.tick_with(c, in, out, [&s](const auto& t, auto& o) {
      if (t.slot.on_schedule) {
        o.slot = t.slot;
        o.sample = t.sample;
      } else {
        off_schedule(s, t, o);
      }
    });
  }

  // stage::PrerenderedFrames: the frame rendered on the nominal schedule.
  const HmdFrame& frame(int64_t f) override { return render(f, -1); }
  void retire_before(int64_t f) override;

  int64_t speculated = 0, fallbacks = 0;  // pixels each way (statistics)

 private:
  template <class S, class In, class Out>
  __attribute__((noinline)) static void off_schedule(const S& s, const In& t, Out& o) {
    s.compute(t, o);
  }
  // Rendered on first use, with the front buffers of that moment (`generation`: the buffers' generation then).
  const HmdFrame& render(int64_t f, int64_t generation);
  int64_t generation_at_render(int64_t f) const;
  void rotate(const stage::LensToken& t, int64_t c, stage::RotatedToken& o);
  void fetch(const stage::AddressToken& t, stage::FetchToken& o);

  FunctionalModel model_;
  const dp::DisplayMemorySet& mem_;
  const dp::OrientationStream& o_;
  const stage::LensVectorStage& lens_;
  stage::OrientationStage& orientation_;
  const stage::AddressStage& address_;
  const stage::MemoryReadStage& memories_;
  int64_t rotate_to_scanout_, extra_lead_;
  bool register_on_schedule_ = false;
  std::map<int64_t, std::pair<int64_t, std::unique_ptr<HmdFrame>>> frames_;
};

}  // namespace arp::scm
