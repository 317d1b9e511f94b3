#include "HostWritePort.hpp"

#include <algorithm>
#include <limits>

#include "common/InputError.hpp"
#include "common/IntegerDivision.hpp"

namespace arp::stage {

namespace {
constexpr int64_t kNever = std::numeric_limits<int64_t>::min();
}  // namespace

void check_host_jobs(const std::vector<HostWriteJob>& jobs, const dp::ArpConfig& c, const std::string& source) {
  const uint64_t max_depth = (uint64_t{1} << c.memory.depth_bits) - 1;
  const uint64_t max_color = c.memory.color_bits() >= 32 ? 0xffffffffull : (uint64_t{1} << c.memory.color_bits()) - 1;
  for (size_t j = 0; j < jobs.size(); ++j) {
    const auto& job = jobs[j];
    const std::string place = "job " + std::to_string(j);
    if (job.eye < 0 || job.eye >= c.timing.eyes) throw InputError(source, place, "eye " + std::to_string(job.eye) + " does not exist");
    if (job.memory < 0 || job.memory >= c.memory.count)
      throw InputError(source, place, "memory " + std::to_string(job.memory) + " does not exist");
    if (j > 0 && job.start_ps < jobs[j - 1].start_ps) throw InputError(source, place, "start times must not decrease");
    for (size_t i = 0; i < job.texels.size(); ++i) {
      const auto& t = job.texels[i];
      if (t.face > 5 || t.x >= c.memory.face_size || t.y >= c.memory.face_size || t.color > max_color ||
          t.depth > max_depth)
        throw InputError(source, place + " texel " + std::to_string(i), "face, position, colour or depth out of range");
    }
  }
}

SwapPoint next_swap_after(const dp::VideoTiming& t, const dp::PipelineSchedule& s, int64_t ps) {
  const int64_t F = t.frame_cycles();
  const int64_t off = s.swap_cycle(0);
  int64_t f = floor_div(t.ps_to_cycle_floor(ps) - off, F);
  while (t.cycles_to_ps(s.swap_cycle(f)) <= ps) ++f;
  while (t.cycles_to_ps(s.swap_cycle(f - 1)) > ps) --f;
  return {f, s.swap_cycle(f), t.cycles_to_ps(s.swap_cycle(f))};
}

std::vector<HostJobTiming> plan_host_jobs(const std::vector<HostWriteJob>& jobs, const dp::ArpConfig& c) {
  const dp::VideoTiming t(c.timing);
  const dp::PipelineSchedule s(c);
  const int64_t hz = c.timed.host_clock_hz;
  const int64_t bw = c.timed.host_texels_per_cycle;
  std::vector<int64_t> free_after(static_cast<size_t>(c.timing.eyes * c.memory.count), kNever);
  std::vector<HostJobTiming> out;
  int64_t next_cycle = kNever;  // first host edge the port is free
  for (const auto& j : jobs) {
    const size_t b = static_cast<size_t>(j.eye * c.memory.count + j.memory);
    int64_t n = dp::clock_cycle_at_or_after(j.start_ps, hz);
    if (free_after[b] != kNever) n = std::max(n, dp::clock_cycle_at_or_after(free_after[b] + 1, hz));
    if (next_cycle != kNever) n = std::max(n, next_cycle);
    const int64_t cycles = std::max<int64_t>(1, (static_cast<int64_t>(j.texels.size()) + bw - 1) / bw);
    HostJobTiming r;
    r.start_ps = dp::clock_cycle_to_ps(n, hz);
    r.commit_ps = dp::clock_cycle_to_ps(n + cycles - 1, hz);
    const SwapPoint sw = next_swap_after(t, s, r.commit_ps);
    r.swap_ps = sw.ps;
    r.swap_frame = sw.frame;
    free_after[b] = sw.ps;
    next_cycle = n + cycles;
    out.push_back(r);
  }
  return out;
}

PlannedHostWrites::PlannedHostWrites(const dp::ArpConfig& c, const std::vector<HostWriteJob>& jobs)
    : jobs_(jobs), plan_(plan_host_jobs(jobs, c)) {}

int PlannedHostWrites::at_vertical_blank(int64_t swap_ps, dp::DisplayMemorySet& mem) {
  int swaps = 0;
  for (; next_ < jobs_.size() && plan_[next_].commit_ps < swap_ps; ++next_) {
    const HostWriteJob& j = jobs_[next_];
    dp::DisplayMemoryBank& b = mem.bank(j.eye, j.memory);
    if (j.clear_first) b.clear_back();
    for (const TexelWrite& w : j.texels) b.write(w.face, w.x, w.y, w.color, w.depth);
    b.commit();
    b.vblank();
    ++swaps;
  }
  return swaps;
}

HostWritePort::HostWritePort(const dp::ArpConfig& c, const std::vector<HostWriteJob>& jobs, dp::DisplayMemorySet& mem)
    : jobs_(jobs),
      mem_(mem),
      timing_(c.timing),
      sched_(c),
      hz_(c.timed.host_clock_hz),
      per_cycle_(c.timed.host_texels_per_cycle),
      count_(c.memory.count),
      commit_ps_(static_cast<size_t>(c.timing.eyes * c.memory.count), kNever),
      free_after_ps_(commit_ps_.size(), kNever) {}

int64_t HostWritePort::next_active_cycle(int64_t host_cycle) const {
  if (busy) return host_cycle;
  if (next_ >= jobs_.size()) return std::numeric_limits<int64_t>::max();
  const HostWriteJob& j = jobs_[next_];
  const size_t b = static_cast<size_t>(j.eye * count_ + j.memory);
  int64_t n = std::max(host_cycle, dp::clock_cycle_at_or_after(j.start_ps, hz_));
  if (free_after_ps_[b] != kNever) n = std::max(n, dp::clock_cycle_at_or_after(free_after_ps_[b] + 1, hz_));
  return n;
}

void HostWritePort::tick(int64_t host_cycle) {
  const int64_t now = dp::clock_cycle_to_ps(host_cycle, hz_);
  if (!busy) {
    if (next_ >= jobs_.size()) return;
    const HostWriteJob& j = jobs_[next_];
    const size_t b = static_cast<size_t>(j.eye * count_ + j.memory);
    if (now < j.start_ps || (free_after_ps_[b] != kNever && now <= free_after_ps_[b])) return;
    busy = true;
    job = static_cast<int32_t>(next_);
    pos_ = 0;
    if (j.clear_first) mem_.bank(j.eye, j.memory).clear_back();
    HostJobTiming r;
    r.start_ps = now;
    done_.push_back(r);
  }
  const HostWriteJob& j = jobs_[next_];
  dp::DisplayMemoryBank& bank = mem_.bank(j.eye, j.memory);
  const size_t end = std::min(j.texels.size(), pos_ + static_cast<size_t>(per_cycle_));
  texels_written += static_cast<int64_t>(end - pos_);
  for (; pos_ < end; ++pos_) {
    const TexelWrite& w = j.texels[pos_];
    bank.write(w.face, w.x, w.y, w.color, w.depth);
  }
  if (pos_ == j.texels.size()) {
    bank.commit();
    const size_t b = static_cast<size_t>(j.eye * count_ + j.memory);
    commit_ps_[b] = now;
    const SwapPoint sw = next_swap_after(timing_, sched_, now);
    free_after_ps_[b] = sw.ps;
    HostJobTiming& r = done_.back();
    r.commit_ps = now;
    r.swap_ps = sw.ps;
    r.swap_frame = sw.frame;
    busy = false;
    ++next_;
  }
}

}  // namespace arp::stage
