#include "PipelineSchedule.hpp"

#include <algorithm>

namespace arp::dp {

namespace {
__extension__ typedef __int128 i128;
constexpr int64_t kPsPerSecond = 1'000'000'000'000;
}  // namespace

PipelineSchedule::PipelineSchedule(const ArpConfig& c)
    : timing_(c.timing), latch_extra_(c.pipeline.latch_lead_cycles) {
  // Walk back from the slot: scan-out takes the pixel latency(scan_out) cycles early, and each
  // earlier stage must have it visible by then.
  int64_t d = 0;
  for (int s = kStageCount - 1; s >= 0; --s) {
    d += c.timed.stage[static_cast<size_t>(s)].latency_cycles;
    to_scanout_[static_cast<size_t>(s)] = d;
  }
  issue_lead_ = d + 1 + c.timed.issue_slack_cycles;  // +1: the issue FIFO's register
  // Slack delays nothing inside the pipeline: it waits in the scan-out FIFO.
  for (auto& v : to_scanout_) v += c.timed.issue_slack_cycles;
  int64_t last = 0;
  for (int y = 0; y < c.timing.v_active; ++y) last = std::max(last, timing_.line_start_cycle(0, y));
  swap_offset_ = last + c.timing.h_total();
}

int64_t clock_cycle_to_ps(int64_t cycle, int64_t hz) {
  return static_cast<int64_t>(static_cast<i128>(cycle) * kPsPerSecond / hz);
}

int64_t clock_cycle_at_or_after(int64_t ps, int64_t hz) {
  if (ps <= 0) return 0;
  // Smallest n with floor(n * 1e12 / hz) >= ps  <=>  n * 1e12 >= ps * hz.
  const i128 num = static_cast<i128>(ps) * hz;
  return static_cast<int64_t>((num + kPsPerSecond - 1) / kPsPerSecond);
}

}  // namespace arp::dp
