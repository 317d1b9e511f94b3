// The video timing generator: drives the panel's scan position and issues
// each active pixel into the pipeline `issue_lead` clocks before its slot
// (the schedule of the pipeline it feeds). The slot a clock ahead is decoded
// now and becomes due next clock (a pure function of the clock: the same
// behaviour), so a pixel is never copied out right after its fields were
// written. If the first FIFO is not ready the pixel waits in a backlog and
// goes as soon as it can -- late, so scan-out will count it as an underflow,
// but never lost.
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "RingIndex.hpp"
#include "ScanTiming.hpp"
#include "StageContext.hpp"
#include "StageInfo.hpp"

namespace arp::stage {

class VideoTimingStage {
 public:
  using Input = void;
  using Output = PixelSlot;
  static constexpr const StageInfo& kInfo = kVideoTimingInfo;
  explicit VideoTimingStage(const StageContext& ctx);

  const ScanTiming& scan() const { return scan_; }
  int64_t issue_lead() const { return lead_; }
  // First and last cycle a run needs: the first issue, and the last frame's swap.
  int64_t first_cycle() const { return scan_.timing().frame_start_cycle(scan_.first_frame()) - lead_; }
  int64_t end_cycle() const { return sched_.run_end_cycle(scan_.end_frame()); }

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
        head_ = ring_index(head_ + 1, ring_.size());
        --count_;
        issued = true;
      } else {
        ++issue_stalls_;
        out.note_blocked();
      }
    }
    backlog = static_cast<uint32_t>(count_ - (ahead ? 1 : 0));
    if (track_position) follow_panel(cycle);
  }

  // Nothing waiting to be issued.
  bool idle() const { return backlog == 0; }
  // With the whole pipeline idle: the first cycle at or after c (before
  // `end`) at which anything can happen -- an issue or a buffer swap. Models
  // skip the cycles in between; nothing observable happens in them.
  int64_t next_busy_cycle(int64_t c, int64_t end) const;

  int64_t issue_stalls() const { return issue_stalls_; }
  // The panel's scan position is only computed for waveforms.
  bool track_position = false;
  void set_probing(bool on) { track_position = on; }
  template <class Fn>
  void for_each_probe(Fn&& fn) const {
    fn("frame", frame_count);
    fn("v_count", v_count);
    fn("h_count", h_count);
    fn("display_enable", display_enable);
    fn("hsync", hsync);
    fn("vsync", vsync);
    fn("vblank", vblank);
    fn("valid_out", issued);
    fn("issue_backlog", backlog);
  }
  // Traced: the panel's scan position now, and the issue handshake.
  int32_t h_count = 0, v_count = 0;
  int64_t frame_count = 0;
  bool display_enable = false, hsync = false, vsync = false, vblank = false;
  bool issued = false;
  uint32_t backlog = 0;

 private:
  // The slot issued at clock `issue_cycle`, if any, onto the ring's tail.
  bool decode_into_ring(int64_t issue_cycle) {
    if (count_ == ring_.size()) grow();
    PixelSlot& s = ring_[ring_index(head_ + count_, ring_.size())];
    if (!scan_.decode(issue_cycle + lead_, s, issue_cursor_)) return false;
    ++count_;
    return true;
  }
  void grow();
  void follow_panel(int64_t cycle);

  ScanTiming scan_;
  dp::PipelineSchedule sched_;
  int64_t lead_;
  int64_t next_decode_ = std::numeric_limits<int64_t>::min();
  std::vector<PixelSlot> ring_ = std::vector<PixelSlot>(64);  // the backlog
  size_t head_ = 0, count_ = 0;
  ScanTiming::Cursor issue_cursor_, panel_cursor_;
  int64_t issue_stalls_ = 0;
};

}  // namespace arp::stage
