#include "FrameSpeculation.hpp"

namespace arp::cycle {

FrameSpeculation::FrameSpeculation(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem,
                                   const dp::OrientationStream& o)
    : model_(c), mem_(mem), o_(o) {}

const HmdFrame& FrameSpeculation::frame(int64_t f, int64_t swaps) {
  auto it = frames_.find(f);
  if (it == frames_.end()) {
    auto fr = std::make_unique<HmdFrame>();
    model_.render(mem_, o_, f, *fr);
    it = frames_.emplace(f, std::make_pair(swaps, std::move(fr))).first;
  }
  return *it->second.second;
}

int64_t FrameSpeculation::swaps_at_render(int64_t f) const {
  const auto it = frames_.find(f);
  return it == frames_.end() ? -1 : it->second.first;
}

void FrameSpeculation::retire_before(int64_t f) {
  while (!frames_.empty() && frames_.begin()->first < f) frames_.erase(frames_.begin());
}

}  // namespace arp::cycle
