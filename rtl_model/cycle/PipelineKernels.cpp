#include "PipelineKernels.hpp"

#include <algorithm>

namespace arp::cycle {

namespace {
int lat(const dp::ArpConfig& c, dp::Stage s) { return c.timed.stage[static_cast<size_t>(s)].latency_cycles; }
}  // namespace

PipelineKernels::PipelineKernels(const TimedInputs& in)
    : arith(in.config),
      scan(in.config, in.first_frame, in.frames),
      latch(arith, *in.orientation),
      host(in.config, in.host_jobs, *in.memories),
      swapper(in.config, *in.memories, &host),
      lens(lat(in.config, dp::Stage::Lens)),
      rotate(lat(in.config, dp::Stage::Rotate)),
      address(lat(in.config, dp::Stage::Address)),
      fetch(lat(in.config, dp::Stage::Fetch)),
      compose(lat(in.config, dp::Stage::Compose)),
      filter(lat(in.config, dp::Stage::Filter)),
      scanout(arith, scan, *in.orientation, in.sink),
      mem_(in.memories),
      stalls_(in.stalls),
      any_stalls_(!in.stalls.empty()),
      orientation_(in.orientation),
      rotate_to_scanout_(scan.schedule().stage_to_scanout(dp::Stage::Rotate)) {
  if (in.before_frame) swapper.set_host_model(in.before_frame, in.first_frame + in.frames);
}

void PipelineKernels::set_speculation(bool on) {
  if (!on) spec_.reset();
  else if (!spec_) spec_ = std::make_unique<FrameSpeculation>(arith.config(), *mem_, *orientation_);
}

bool PipelineKernels::speculate_rotate(const LensToken& t, int64_t c, RotatedToken& o) {
  // A latch pixel decides for itself and every pixel until the next latch:
  // on its nominal clock it reads what the functional model assumed;
  // otherwise it may still have read the same sample.
  if (t.slot.latch) {
    const int64_t nominal = t.slot.slot_cycle - rotate_to_scanout_;
    const int64_t extra = arith.config().pipeline.latch_lead_cycles;
    register_on_schedule_ = c == nominal || latch.register_sample(nominal - extra) == latch.sample;
  }
  if (!register_on_schedule_) {
    ++spec_->fallbacks;
    return false;
  }
  spec_->frame(t.slot.frame, swapper.generation());  // rendered on the frame's first pixel
  o.slot = t.slot;
  o.slot.on_schedule = true;
  o.sample = latch.sample;
  ++spec_->speculated;
  return true;
}

void PipelineKernels::recompute_address(const AddressToken& t, FetchToken& o) {
  LensToken l;
  RotatedToken r;
  AddressToken a;
  arith.lens(t.slot, l);
  arith.rotate(l, arith.matrix((*orientation_)[t.sample].q), t.sample, r);
  arith.address(r, a);
  arith.fetch(a, *mem_, o);
  o.slot.on_schedule = false;
  ++spec_->fallbacks;
}

int64_t PipelineKernels::next_busy_cycle(int64_t c, int64_t end) const {
  const auto& t = scan.timing();
  const auto& s = scan.schedule();
  const int64_t lead = s.issue_lead();
  const int64_t h = t.config().h_total();
  int64_t slot = c + lead;
  PixelSlot p;
  // Walk line starts through blanking; at most a frame's worth of lines.
  ScanTiming::Cursor cur;
  for (int i = 0; i < 2 * t.config().v_total() + 4 && !scan.decode(slot, p, cur) && slot < end + lead; ++i) {
    const ScanPosition& pos = scan.position(slot, cur);
    // To the next line start -- or the next field's start, which an interlaced field may reach mid-line.
    const int64_t next_field = t.frame_start_cycle(pos.frame) + (cur.field + 1) * t.field_cycles();
    slot = std::min(slot + (pos.hpos == 0 ? h : h - pos.hpos), next_field);
  }
  int64_t next = std::max(c, slot - lead);
  const int64_t F = t.frame_cycles();
  const int64_t f = (c - s.swap_cycle(0)) / F;
  for (int64_t g = f - 1; g <= f + 1; ++g)
    if (s.swap_cycle(g) >= c && s.swap_cycle(g) < next) next = s.swap_cycle(g);
  return std::min(next, end);
}

std::array<StageStats, dp::kStageCount> PipelineKernels::stage_stats() const {
  std::array<StageStats, dp::kStageCount> s{};
  s[0] = lens.stats();
  s[1] = rotate.stats();
  s[2] = address.stats();
  s[3] = fetch.stats();
  s[4] = compose.stats();
  s[5] = filter.stats();
  s[6].latency_cycles = lat(arith.config(), dp::Stage::ScanOut);
  s[6].min_cycles = s[6].max_cycles = s[6].latency_cycles;
  s[6].mean_cycles = s[6].latency_cycles;
  return s;
}

}  // namespace arp::cycle
