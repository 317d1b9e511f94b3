#include "VideoTimingStage.hpp"

#include <algorithm>

namespace arp::stage {

VideoTimingStage::VideoTimingStage(const StageContext& ctx)
    : scan_(ctx.config(), ctx.in.first_frame, ctx.in.frames, ctx.in.timed_frames), sched_(ctx.schedule), lead_(ctx.schedule.issue_lead()) {}

void VideoTimingStage::grow() {
  std::vector<PixelSlot> r(ring_.size() * 2);
  for (size_t i = 0; i < count_; ++i) r[i] = ring_[ring_index(head_ + i, ring_.size())];
  ring_.swap(r);
  head_ = 0;
}

void VideoTimingStage::follow_panel(int64_t cycle) {
  const ScanPosition& p = scan_.position(cycle, panel_cursor_);
  h_count = p.hpos;
  v_count = p.line;
  frame_count = p.frame;
  display_enable = p.active;
  hsync = p.hsync;
  vsync = p.vsync;
  vblank = p.vblank;
}

int64_t VideoTimingStage::next_busy_cycle(int64_t c, int64_t end) const {
  const auto& t = scan_.timing();
  const int64_t h = t.config().h_total();
  int64_t slot = c + lead_;
  PixelSlot p;
  // Walk line starts through blanking; at most a frame's worth of lines.
  ScanTiming::Cursor cur;
  for (int i = 0; i < 2 * t.config().v_total() + 4 && !scan_.decode(slot, p, cur) && slot < end + lead_; ++i) {
    const ScanPosition& pos = scan_.position(slot, cur);
    // To the next line start -- or the next field's start, which an interlaced field may reach mid-line.
    const int64_t next_field = t.frame_start_cycle(pos.frame) + (cur.field + 1) * t.field_cycles();
    slot = std::min(slot + (pos.hpos == 0 ? h : h - pos.hpos), next_field);
  }
  int64_t next = std::max(c, slot - lead_);
  const int64_t F = t.frame_cycles();
  const int64_t f = (c - sched_.swap_cycle(0)) / F;
  for (int64_t g = f - 1; g <= f + 1; ++g)
    if (sched_.swap_cycle(g) >= c && sched_.swap_cycle(g) < next) next = sched_.swap_cycle(g);
  return std::min(next, end);
}

}  // namespace arp::stage
