#include "ScanTiming.hpp"

#include <algorithm>
#include <utility>

#include "common/IntegerDivision.hpp"

namespace arp::stage {

ScanTiming::ScanTiming(const dp::ArpConfig& c, int64_t first_frame, int64_t frames, FrameWindows windows)
    : timing_(c.timing),
      tc_(c.timing),
      latch_(c),
      first_(first_frame),
      end_(first_frame + frames),
      windows_(std::move(windows)),
      field_cycles_(timing_.field_cycles()),
      row_pixels_(c.timing.eye_scan == dp::EyeScan::SideBySide ? c.timing.eyes * c.timing.h_active
                                                                : c.timing.h_active),
      h_total_(tc_.h_total()),
      lines_per_field_(static_cast<int>(field_cycles_ / h_total_)),
      hsync_begin_(row_pixels_ + tc_.h_front_porch),
      hsync_end_(row_pixels_ + tc_.h_front_porch + tc_.h_sync),
      side_by_side_(tc_.eye_scan == dp::EyeScan::SideBySide) {
  int64_t last = 0;
  for (int y = 0; y < tc_.v_active; ++y) last = std::max(last, timing_.line_start_cycle(0, y));
  last_offset_ = last + row_pixels_ - 1;
}

ScanPosition ScanTiming::position(int64_t cycle) const {
  Cursor c;
  return position(cycle, c);
}

// The full position of a cycle that does not follow the last one on its line.
void ScanTiming::reposition(int64_t cycle, Cursor& cur) const {
  const int fields = tc_.fields_per_frame;
  ScanPosition& p = cur.pos;
  const int64_t F = timing_.frame_cycles();
  p.frame = floor_div(cycle, F);
  const int64_t o = cycle - p.frame * F;
  cur.field = static_cast<int>(o / field_cycles_);
  const int64_t of = o - cur.field * field_cycles_;
  p.line = static_cast<int32_t>(of / h_total_);
  p.hpos = static_cast<int32_t>(of % h_total_);
  const int y = p.line * fields + cur.field;
  p.vblank = y >= tc_.v_active;
  const int active_lines = (tc_.v_active - cur.field + fields - 1) / fields;
  const int vs0 = active_lines + tc_.v_front_porch / fields;
  p.vsync = tc_.v_sync > 0 && p.line >= vs0 && p.line < vs0 + std::max(1, tc_.v_sync / fields);
}

bool ScanTiming::in_run(int64_t frame) const { return frame >= first_ && frame < end_ && windows_.contains(frame); }

}  // namespace arp::stage
