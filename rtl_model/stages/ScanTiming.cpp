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

const ScanPosition& ScanTiming::position(int64_t cycle, Cursor& cur) const {
  const int fields = tc_.fields_per_frame;
  ScanPosition& p = cur.pos;
  if (cycle == cur.cycle) return p;
  // (An interlaced field may end part-way through its last line: never step there.)
  const bool step = cycle == cur.cycle + 1 && p.hpos + 1 < h_total_ && (fields == 1 || p.line < lines_per_field_);
  cur.cycle = cycle;
  if (step) {
    ++p.hpos;  // the same line: only the horizontal flags change
  } else {
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
  p.active = !p.vblank && p.hpos < row_pixels_;
  p.hsync = p.hpos >= hsync_begin_ && p.hpos < hsync_end_;
  return p;
}

bool ScanTiming::decode(int64_t slot_cycle, PixelSlot& out, Cursor& cur) const {
  const ScanPosition& p = position(slot_cycle, cur);
  if (!p.active) return false;
  if (cur.checked_frame != p.frame) {  // once a frame: within the run, and in its windows
    cur.checked_frame = p.frame;
    cur.decoded = p.frame >= first_ && p.frame < end_ && windows_.contains(p.frame);
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

}  // namespace arp::stage
