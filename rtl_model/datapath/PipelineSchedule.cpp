#include "PipelineSchedule.hpp"

#include <algorithm>
#include <limits>

namespace arp::dp {

namespace {
__extension__ typedef __int128 i128;
constexpr int64_t kPsPerSecond = 1'000'000'000'000;
}  // namespace

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

ClockTimeCursor::ClockTimeCursor(int64_t hz)
    : hz_(hz), q_(kPsPerSecond / hz), r_(kPsPerSecond % hz), cycle_(std::numeric_limits<int64_t>::min()) {}

void ClockTimeCursor::seek(int64_t cycle) {
  // floor(cycle * 1e12 / hz) and its remainder, for any sign.
  const i128 num = static_cast<i128>(cycle) * kPsPerSecond;
  i128 q = num / hz_, r = num % hz_;
  if (r < 0) {
    r += hz_;
    --q;
  }
  cycle_ = cycle;
  ps_ = static_cast<int64_t>(q);
  rem_ = static_cast<int64_t>(r);
}

int64_t clock_cycle_to_ps(int64_t cycle, int64_t hz) {
  const i128 num = static_cast<i128>(cycle) * kPsPerSecond;
  i128 q = num / hz;
  if (num % hz < 0) --q;  // floor, also before time 0
  return static_cast<int64_t>(q);
}

int64_t clock_cycle_at_or_after(int64_t ps, int64_t hz) {
  // Smallest n with floor(n * 1e12 / hz) >= ps  <=>  n * 1e12 >= ps * hz  <=>  n >= ceil(ps * hz / 1e12).
  const i128 num = static_cast<i128>(ps) * hz;
  i128 q = num / kPsPerSecond;
  if (num % kPsPerSecond > 0) ++q;  // ceil, for either sign
  return static_cast<int64_t>(q);
}

}  // namespace arp::dp
