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
  // Inline, twice a pixel clock: the next clock on the same line only moves the horizontal flags.
  const ScanPosition& position(int64_t cycle, Cursor& cur) const {  // a reference: no copy of a just-written struct
    ScanPosition& p = cur.pos;
    if (cycle == cur.cycle) return p;
    // (An interlaced field may end part-way through its last line: never step there.)
    const bool step = cycle == cur.cycle + 1 && p.hpos + 1 < h_total_ &&
                      (tc_.fields_per_frame == 1 || p.line < lines_per_field_);
    cur.cycle = cycle;
    if (step) ++p.hpos;
    else reposition(cycle, cur);
    p.active = !p.vblank && p.hpos < row_pixels_;
    p.hsync = p.hpos >= hsync_begin_ && p.hpos < hsync_end_;
    return p;
  }
  bool decode(int64_t slot_cycle, PixelSlot& out, Cursor& cur) const {
    const ScanPosition& p = position(slot_cycle, cur);
    if (!p.active) return false;
    if (cur.checked_frame != p.frame) {  // once a frame: within the run, and in its windows
      cur.checked_frame = p.frame;
      cur.decoded = in_run(p.frame);
    }
    if (!cur.decoded) return false;
    out.frame = p.frame;
    out.slot_cycle = slot_cycle;
    out.y = p.line * tc_.fields_per_frame + cur.field;
    if (side_by_side_) {  // an active hpos is below eyes x h_active: the eye by subtraction, no divide
      int eye = 0, x = p.hpos;
      while (x >= tc_.h_active) {
        x -= tc_.h_active;
        ++eye;
      }
      out.eye_first = static_cast<uint8_t>(eye);
      out.eye_count = 1;
      out.x = x;
    } else {
      out.eye_first = 0;
      out.eye_count = static_cast<uint8_t>(tc_.eyes);
      out.x = p.hpos;
    }
    out.latch = latch_.is_latch_point(out.eye_first, out.x, out.y);
    return true;
  }
  // The last active slot of a frame.
  int64_t last_slot(int64_t frame) const { return timing_.frame_start_cycle(frame) + last_offset_; }

 private:
  void reposition(int64_t cycle, Cursor& cur) const;
  bool in_run(int64_t frame) const;  // a frame decoded: in the run, and in its windows

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
