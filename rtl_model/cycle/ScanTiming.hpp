// The video timing generator's logic: which pixel (if any) a pixel-clock slot
// scans out, the panel's scan position for the waveform, and the issue of
// each pixel `issue_lead` cycles before its slot. If the first FIFO is not
// ready the pixel waits in a backlog and goes as soon as it can -- late, so
// scan-out will count it as an underflow, but never lost.
#pragma once
#include <cstdint>
#include <vector>
#include <limits>

#include "PixelTokens.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::cycle {

struct ScanPosition {
  int64_t frame = 0;
  int32_t line = 0;  // line of the field, in scan order
  int32_t hpos = 0;  // pixel clock within the line
  bool active = false, hsync = false, vsync = false, vblank = false;
};

class ScanTiming {
 public:
  // Pixels of frames [first_frame, first_frame + frames) are issued.
  ScanTiming(const dp::ArpConfig& c, int64_t first_frame, int64_t frames);

  const dp::VideoTiming& timing() const { return timing_; }
  const dp::PipelineSchedule& schedule() const { return sched_; }
  int64_t first_frame() const { return first_; }
  int64_t end_frame() const { return end_; }

  // The pixel scanned out at `slot_cycle`; false in blanking or outside the run's frames.
  bool decode(int64_t slot_cycle, PixelSlot& out) const { return decode(slot_cycle, out, scratch_); }
  ScanPosition position(int64_t cycle) const;

  // Position of consecutive cycles without divisions: steps from the last
  // cycle asked for when it is the next one (the common case), else recomputes.
  struct Cursor {
    int64_t cycle = std::numeric_limits<int64_t>::min();
    int field = 0;
    ScanPosition pos;
  };
  const ScanPosition& position(int64_t cycle, Cursor& cur) const;  // a reference: no copy of a just-written struct
  bool decode(int64_t slot_cycle, PixelSlot& out, Cursor& cur) const;
  // The last active slot of a frame.
  int64_t last_slot(int64_t frame) const { return timing_.frame_start_cycle(frame) + last_offset_; }
  // First and last cycle a run needs: the first issue, and the last frame's swap.
  int64_t first_cycle() const { return timing_.frame_start_cycle(first_) - sched_.issue_lead(); }
  int64_t end_cycle() const { return sched_.swap_cycle(end_ - 1) + 1; }

  // One clock of the issue logic. The slot a clock ahead is decoded now and
  // becomes due next clock (a pure function of the clock: same behaviour),
  // so a pixel is never copied out right after its fields were written.
  template <class OutFifo>
  void tick(int64_t cycle, OutFifo& out) {
    // Clocks a model skipped issue nothing (it only skips when nothing is due).
    if (next_decode_ < cycle) next_decode_ = cycle;
    if (next_decode_ == cycle) decode_into_ring(next_decode_++);
    const size_t due = count_;  // pixels whose issue clock has come
    const bool ahead = decode_into_ring(next_decode_++);
    issued = false;
    if (due > 0) {
      if (out.can_write()) {
        out.write(ring_[head_], cycle);
        head_ = (head_ + 1) % ring_.size();
        --count_;
        issued = true;
      } else {
        ++issue_stalls_;
        out.note_blocked();
      }
    }
    backlog = static_cast<uint32_t>(count_ - (ahead ? 1 : 0));
    if (!track_position) return;
    const ScanPosition& p = position(cycle, panel_cursor_);
    h_count = p.hpos;
    v_count = p.line;
    frame_count = p.frame;
    display_enable = p.active;
    hsync = p.hsync;
    vsync = p.vsync;
    vblank = p.vblank;
  }
  // The panel's scan position is only computed for waveforms.
  bool track_position = false;
  int64_t issue_stalls() const { return issue_stalls_; }

  // Traced: the panel's scan position now, and the issue handshake.
  int32_t h_count = 0, v_count = 0;
  int64_t frame_count = 0;
  bool display_enable = false, hsync = false, vsync = false, vblank = false;
  bool issued = false;
  uint32_t backlog = 0;

 private:
  dp::VideoTiming timing_;
  dp::PipelineSchedule sched_;
  dp::VideoTimingConfig tc_;
  dp::LatchRule latch_;
  int64_t first_, end_;
  int64_t field_cycles_;
  int row_pixels_;      // active pixel clocks per line
  int64_t last_offset_;
  // The slot issued at clock `issue_cycle`, if any, onto the ring's tail.
  bool decode_into_ring(int64_t issue_cycle) {
    if (count_ == ring_.size()) grow();
    PixelSlot& s = ring_[(head_ + count_) % ring_.size()];
    if (!decode(issue_cycle + sched_.issue_lead(), s, issue_cursor_)) return false;
    ++count_;
    return true;
  }
  int64_t next_decode_ = std::numeric_limits<int64_t>::min();
  void grow() {
    std::vector<PixelSlot> r(ring_.size() * 2);
    for (size_t i = 0; i < count_; ++i) r[i] = ring_[(head_ + i) % ring_.size()];
    ring_.swap(r);
    head_ = 0;
  }
  std::vector<PixelSlot> ring_ = std::vector<PixelSlot>(64);  // the backlog
  size_t head_ = 0, count_ = 0;
  Cursor issue_cursor_, panel_cursor_;
  mutable Cursor scratch_;
  int64_t issue_stalls_ = 0;
};

}  // namespace arp::cycle
