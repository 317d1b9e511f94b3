// The host's write port into display memory, on its own clock. Jobs are
// served in order: a job starts at the first host clock edge at or after its
// start time once the previous job is done and its memory's last commit has
// been swapped to the front (strictly before the edge); it then stores
// timed.host_texels_per_cycle texels per host clock into the back buffer and
// commits on the clock of its last texel. The swap happens at the first
// vertical blank strictly after the commit.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::stage {

struct TexelWrite {
  uint8_t face;
  uint16_t x, y;
  uint32_t color, depth;
};

struct HostWriteJob {
  int64_t start_ps = 0;     // earliest start (absolute simulated time)
  int eye = 0, memory = 0;
  bool clear_first = false;  // empty the back buffer first (a bulk clear, modelled as free)
  std::vector<TexelWrite> texels;
};

struct HostJobTiming {
  int64_t start_ps = 0, commit_ps = 0, swap_ps = 0;
  int64_t swap_frame = 0;  // the frame whose vertical blank swaps it (its image shows from frame + 1)
};

// InputError naming `source`, the job index and the reason for a job the memories cannot take.
void check_host_jobs(const std::vector<HostWriteJob>& jobs, const dp::ArpConfig& c, const std::string& source);

// When each job starts, commits and is swapped -- the rule above, computed
// directly. The cycle-accurate write port reproduces it edge by edge (tested).
std::vector<HostJobTiming> plan_host_jobs(const std::vector<HostWriteJob>& jobs, const dp::ArpConfig& c);

// The first vertical blank strictly after `ps`: its frame and time.
struct SwapPoint {
  int64_t frame, cycle, ps;
};
SwapPoint next_swap_after(const dp::VideoTiming& t, const dp::PipelineSchedule& s, int64_t ps);

// The untimed levels' host writes: the planned jobs applied whole at the
// vertical blank that swaps them (their texels are in the back buffer, which
// nothing reads before that swap, so the frames are the same).
class PlannedHostWrites {
 public:
  PlannedHostWrites(const dp::ArpConfig& c, const std::vector<HostWriteJob>& jobs);
  // The vertical blank at absolute `swap_ps`: applies and commits every job
  // committed before it, then swaps those banks. Returns the swaps.
  int at_vertical_blank(int64_t swap_ps, dp::DisplayMemorySet& mem);
  const std::vector<HostJobTiming>& timings() const { return plan_; }

 private:
  const std::vector<HostWriteJob>& jobs_;
  std::vector<HostJobTiming> plan_;
  size_t next_ = 0;
};

class HostWritePort {
 public:
  HostWritePort(const dp::ArpConfig& c, const std::vector<HostWriteJob>& jobs, dp::DisplayMemorySet& mem);

  // The host clock edge `host_cycle` (absolute; time clock_cycle_to_ps(host_cycle, host_clock_hz)).
  void tick(int64_t host_cycle);
  // The first host cycle at or after `host_cycle` at which tick() can do
  // anything (INT64_MAX: never again): the port's clock is gated off while idle.
  int64_t next_active_cycle(int64_t host_cycle) const;
  const std::vector<HostJobTiming>& timings() const { return done_; }
  static constexpr int64_t kNever = std::numeric_limits<int64_t>::min();
  // When bank (eye, memory) last committed (kNever: never).
  int64_t commit_ps(int eye, int memory) const { return commit_ps_[static_cast<size_t>(eye * count_ + memory)]; }

  // Traced.
  bool busy = false;
  int32_t job = -1;
  int64_t texels_written = 0;

 private:
  const std::vector<HostWriteJob>& jobs_;
  dp::DisplayMemorySet& mem_;
  dp::VideoTiming timing_;
  dp::PipelineSchedule sched_;
  int64_t hz_;
  int per_cycle_;
  int count_;
  size_t next_ = 0, pos_ = 0;
  std::vector<int64_t> commit_ps_, free_after_ps_;
  std::vector<HostJobTiming> done_;
};

}  // namespace arp::stage
