#include "FrameSpeculation.hpp"

namespace arp::scm {

FrameSpeculation::FrameSpeculation(const stage::StageContext& ctx, const stage::LensVectorStage& lens,
                                   stage::OrientationStage& orientation, const stage::AddressStage& address,
                                   const stage::MemoryReadStage& memories)
    : model_(ctx.config()),
      mem_(*ctx.in.memories),
      o_(*ctx.in.orientation),
      lens_(lens),
      orientation_(orientation),
      address_(address),
      memories_(memories),
      rotate_to_scanout_(ctx.schedule.stage_to_scanout(dp::Stage::Rotate)),
      extra_lead_(ctx.config().pipeline.latch_lead_cycles) {}

const HmdFrame& FrameSpeculation::render(int64_t f, int64_t generation) {
  auto it = frames_.find(f);
  if (it == frames_.end()) {
    auto fr = std::make_unique<HmdFrame>();
    model_.render(mem_, o_, f, *fr);
    it = frames_.emplace(f, std::make_pair(generation, std::move(fr))).first;
  }
  return *it->second.second;
}

int64_t FrameSpeculation::generation_at_render(int64_t f) const {
  const auto it = frames_.find(f);
  return it == frames_.end() ? -1 : it->second.first;
}

void FrameSpeculation::retire_before(int64_t f) {
  while (!frames_.empty() && frames_.begin()->first < f) frames_.erase(frames_.begin());
}

void FrameSpeculation::rotate(const stage::LensToken& t, int64_t c, stage::RotatedToken& o) {
  orientation_.latch(t.slot, c);
  // A latch pixel decides for itself and every pixel until the next latch:
  // on its nominal clock it reads what the functional model assumed;
  // otherwise it may still have read the same sample.
  if (t.slot.latch) {
    const int64_t nominal = t.slot.slot_cycle - rotate_to_scanout_;
    register_on_schedule_ = c == nominal || orientation_.register_sample(nominal - extra_lead_) == orientation_.sample;
  }
  if (register_on_schedule_) {
    render(t.slot.frame, memories_.swapper().generation());  // rendered on the frame's first pixel
    o.slot = t.slot;
    o.slot.on_schedule = true;
    o.sample = orientation_.sample;
    ++speculated;
    return;
  }
  ++fallbacks;
  stage::LensToken full;  // off the schedule: the view vectors were not read
  lens_.compute(t.slot, full);
  orientation_.rotate(full, orientation_.matrix, orientation_.sample, o);
  o.slot.on_schedule = false;
}

void FrameSpeculation::fetch(const stage::AddressToken& t, stage::FetchToken& o) {
  if (!t.slot.on_schedule) {
    memories_.compute(t, o);
    return;
  }
  if (generation_at_render(t.slot.frame) == memories_.swapper().generation()) {
    o.slot = t.slot;
    o.sample = t.sample;
    o.memories = o.taps = 0;  // no words travel with it
    return;
  }
  // A swap since the frame was rendered: its address again, then the real fetch.
  stage::LensToken l;
  stage::RotatedToken r;
  stage::AddressToken a;
  lens_.compute(t.slot, l);
  orientation_.rotate(l, orientation_.matrix_of(t.sample), t.sample, r);
  address_.compute(r, a);
  memories_.compute(a, o);
  o.slot.on_schedule = false;
  ++fallbacks;
}

}  // namespace arp::scm
