// The scan pattern as counters see it: which pixel (if any) a pixel-clock
// slot scans out, and the panel's scan position. Pure functions of the clock;
// the video timing generator and the scan-out each own one (their counters).
#pragma once
#include <cstdint>
#include <limits>

#include "FrameWindows.hpp"
#include "PixelTokens.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::stage {

struct ScanPosition {
  int64_t frame = 0;
  int32_t line = 0;  // line of the field, in scan order
  int32_t hpos = 0;  // pixel clock within the line
  bool active = false, hsync = false, vsync = false, vblank = false;
};

class ScanTiming {
 public:
  // Pixels of frames [first_frame, first_frame + frames) are decoded -- of
  // those, only the frames in `windows` (a run with detailed windows).
  ScanTiming(const dp::ArpConfig& c, int64_t first_frame, int64_t frames, FrameWindows windows = {});

  const dp::VideoTiming& timing() const { return timing_; }
  int64_t first_frame() const { return first_; }
  int64_t end_frame() const { return end_; }

  // The pixel scanned out at `slot_cycle`; false in blanking or outside the run's (windows') frames.
  bool decode(int64_t slot_cycle, PixelSlot& out) const { return decode(slot_cycle, out, scratch_); }
  ScanPosition position(int64_t cycle) const;

  // Position of consecutive cycles without divisions: steps from the last
  // cycle asked for when it is the next one (the common case), else recomputes.
  struct Cursor {
    int64_t cycle = std::numeric_limits<int64_t>::min();
    int field = 0;
    ScanPosition pos;
    int64_t checked_frame = std::numeric_limits<int64_t>::min();  // the frame `decoded` is for
    bool decoded = false;  // its pixels are decoded: in the run, and in its windows
  };
  const ScanPosition& position(int64_t cycle, Cursor& cur) const;  // a reference: no copy of a just-written struct
  bool decode(int64_t slot_cycle, PixelSlot& out, Cursor& cur) const;
  // The last active slot of a frame.
  int64_t last_slot(int64_t frame) const { return timing_.frame_start_cycle(frame) + last_offset_; }

 private:
  dp::VideoTiming timing_;
  dp::VideoTimingConfig tc_;
  dp::LatchRule latch_;
  int64_t first_, end_;
  FrameWindows windows_;
  int64_t field_cycles_;
  int row_pixels_;      // active pixel clocks per line
  // Per-clock constants, worked out once (position() runs twice a pixel clock).
  int h_total_, lines_per_field_, hsync_begin_, hsync_end_;
  bool side_by_side_;
  int64_t last_offset_;
  mutable Cursor scratch_;
};

}  // namespace arp::stage
