// The pipeline's schedule when no stage stalls: when a pixel is issued, when
// it passes each stage, and so how far ahead of its photon the orientation
// register is sampled. Every fidelity level takes its orientation lead from
// here, so all of them latch the same tracker sample for the same pixel.
//
// Pixel p (scan-out cycle s) is issued at s - issue_lead into the first FIFO,
// visible one cycle later; each stage adds its latency; the scan-out stage
// takes the pixel latency(scan_out) cycles before its slot.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "ArpConfig.hpp"
#include "ClockTime.hpp"
#include "VideoTiming.hpp"

namespace arp::dp {

// A stage as the schedule sees it: its latency, and which of the
// configuration's stages it is (none: a stage an architect inserted).
struct ScheduledStage {
  int latency_cycles = 1;
  int id = -1;  // static_cast<int>(Stage), or -1
};

class PipelineSchedule {
 public:
  // The standard pipeline: the configuration's seven stages and latencies.
  explicit PipelineSchedule(const ArpConfig& c);
  // Any chain of stages after the video timing generator, in data-flow order,
  // ending with scan-out (the detailed model's, e.g. with a register inserted).
  PipelineSchedule(const ArpConfig& c, const std::vector<ScheduledStage>& chain);
  // The standard chain's stages.
  static std::vector<ScheduledStage> standard_chain(const ArpConfig& c);

  // Cycles between issuing a pixel and scanning it out.
  int64_t issue_lead() const { return issue_lead_; }
  // Cycles from the pixel entering stage s to its scan-out slot.
  int64_t stage_to_scanout(Stage s) const { return to_scanout_[static_cast<size_t>(s)]; }
  // The functional model's lead: the latch-point pixel enters the orientation
  // matrix unit this many cycles before its slot, and the register is read
  // pipeline.latch_lead_cycles before that.
  int64_t orientation_lead() const { return stage_to_scanout(Stage::Rotate) + latch_extra_; }
  // Cycle of the first vertical-blank line after frame `frame`'s last active line (the buffer swap).
  int64_t swap_cycle(int64_t frame) const { return timing_.frame_start_cycle(frame) + swap_offset_; }
  // The cycle after the last a timed run of frames [.., end_frame) simulates: the last frame's swap (the rest
  // of its vertical blank is not run).
  int64_t run_end_cycle(int64_t end_frame) const { return swap_cycle(end_frame - 1) + 1; }
  // Cycles from the swap to the next frame's first active pixel.
  int64_t vblank_cycles() const { return timing_.frame_cycles() - swap_offset_; }

 private:
  VideoTiming timing_;
  int64_t issue_lead_;
  int64_t latch_extra_;
  int64_t swap_offset_;
  std::array<int64_t, kStageCount> to_scanout_{};
};

}  // namespace arp::dp
