#include "PipelineSchedule.hpp"

#include <algorithm>
#include <limits>

namespace arp::dp {

std::vector<ScheduledStage> PipelineSchedule::standard_chain(const ArpConfig& c) {
  std::vector<ScheduledStage> chain;
  for (int s = 0; s < kStageCount; ++s) chain.push_back({c.timed.stage[static_cast<size_t>(s)].latency_cycles, s});
  return chain;
}

PipelineSchedule::PipelineSchedule(const ArpConfig& c) : PipelineSchedule(c, standard_chain(c)) {}

PipelineSchedule::PipelineSchedule(const ArpConfig& c, const std::vector<ScheduledStage>& chain)
    : timing_(c.timing), latch_extra_(c.pipeline.latch_lead_cycles) {
  // Walk back from the slot: scan-out takes the pixel latency(scan_out) cycles early, and each
  // earlier stage must have it visible by then.
  int64_t d = 0;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    d += it->latency_cycles;
    if (it->id >= 0) to_scanout_[static_cast<size_t>(it->id)] = d;
  }
  issue_lead_ = d + 1 + c.timed.issue_slack_cycles;  // +1: the issue FIFO's register
  // Slack delays nothing inside the pipeline: it waits in the scan-out FIFO.
  for (auto& v : to_scanout_) v += c.timed.issue_slack_cycles;
  int64_t last = 0;
  for (int y = 0; y < c.timing.v_active; ++y) last = std::max(last, timing_.line_start_cycle(0, y));
  swap_offset_ = last + c.timing.h_total();
}

}  // namespace arp::dp
