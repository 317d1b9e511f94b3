// The fast cycle-accurate model's shortcut, exact by construction and
// checked per pixel. A frame's pixels depend on the clock only through two
// things: which tracker sample the orientation register holds when a latch
// pixel enters the orientation matrix unit, and which buffers are in front
// when a pixel is fetched. On the nominal schedule (no stall) both are what
// the functional model assumes, so the fast model renders each frame once
// with the functional model's vectorised passes -- the same datapath
// arithmetic -- and lets a pixel skip the per-stage arithmetic only while
//  - the register's sample is the one the nominal latch would read, and
//  - no buffer has swapped since the frame was rendered.
// Any other pixel (a stall moved a latch, a fetch crossed a swap) is computed
// stage by stage. The detailed model never speculates; waveform tracing turns
// it off too, so every stage shows its data.
#pragma once
#include <cstdint>
#include <map>
#include <memory>

#include "rtl_model/functional/FunctionalModel.hpp"

namespace arp::cycle {

class FrameSpeculation {
 public:
  FrameSpeculation(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem, const dp::OrientationStream& o);

  // The frame rendered on the nominal schedule (rendered on first use, with
  // the front buffers of that moment; `swaps` = the swap count then).
  const HmdFrame& frame(int64_t f, int64_t swaps);
  // The swap count when frame f was rendered (-1 if it was not).
  int64_t swaps_at_render(int64_t f) const;
  // Forget frames before f.
  void retire_before(int64_t f);

  int64_t speculated = 0, fallbacks = 0;  // pixels each way (statistics)

 private:
  FunctionalModel model_;
  const dp::DisplayMemorySet& mem_;
  const dp::OrientationStream& o_;
  std::map<int64_t, std::pair<int64_t, std::unique_ptr<HmdFrame>>> frames_;
};

}  // namespace arp::cycle
