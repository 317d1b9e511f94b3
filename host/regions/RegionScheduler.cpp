#include "RegionScheduler.hpp"

#include <algorithm>
#include <cmath>

#include "common/InputError.hpp"
#include "common/Units.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"

namespace arp::host {

RegionScheduler::RegionScheduler(const RegionGrid& grid, const RegionConfig& cfg, int face_size, const glm::dvec3& start,
                                 const std::string& source)
    : grid_(grid),
      cfg_(cfg),
      threshold_(cfg.threshold_rad > 0 ? cfg.threshold_rad : dp::texel_angle_rad(face_size)),
      center_(grid.region_of(start)),
      memory_(static_cast<size_t>(grid.count()), 0),
      last_(static_cast<size_t>(cfg.memories), start) {
  if (!(cfg.margin_m >= 0) || cfg.margin_m >= grid.size() / 2)
    throw InputError(source, "margin", "must be at least 0 and less than half the region size (" +
                                           std::to_string(grid.size() / 2) + " m)");
  if (cfg.memories < 1) throw InputError(source, "memories", "must be at least 1");
  assign_from(center_);
}

void RegionScheduler::assign_from(const RegionIndex& c) {
  for (int i = 0; i < grid_.count(); ++i)
    memory_[static_cast<size_t>(i)] = std::min(RegionGrid::ring(grid_.unflat(i), c), cfg_.memories - 1);
}

int RegionScheduler::memory_of_object(int flat_region, const std::pair<RegionIndex, RegionIndex>* span) const {
  if (!span) return memory_of_region(flat_region);
  const auto& [lo, hi] = *span;
  int best = cfg_.memories - 1;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int z = lo.z; z <= hi.z; ++z)
      for (int x = lo.x; x <= hi.x; ++x) best = std::min(best, memory_of_region(grid_.flat({x, y, z})));
  return best;
}

double RegionScheduler::threshold_distance(int m) const {
  const double d = std::max(0.25, (m - 0.5) * grid_.size());
  return d * std::sqrt(2.0 * (1.0 - std::cos(threshold_)));
}

RegionScheduler::Step RegionScheduler::step(const glm::dvec3& p, bool can_reassign) {
  Step s;
  const int N = cfg_.memories;
  std::vector<char> need(static_cast<size_t>(N), 0);
  for (int m = 0; m < N; ++m) need[static_cast<size_t>(m)] = glm::length(p - last_[static_cast<size_t>(m)]) > threshold_distance(m);
  const RegionIndex here = grid_.region_of(p);
  const bool pending = here != center_ && grid_.depth_past(p, center_, here) >= cfg_.margin_m;
  if (pending && need[static_cast<size_t>(N - 1)] && can_reassign) {
    // Re-assign: every memory whose set of regions changes updates now, together.
    const std::vector<int> before = memory_;
    assign_from(here);
    center_ = here;
    ++reassignments_;
    s.reassigned = true;
    for (int i = 0; i < grid_.count(); ++i)
      if (before[static_cast<size_t>(i)] != memory_[static_cast<size_t>(i)]) {
        need[static_cast<size_t>(before[static_cast<size_t>(i)])] = 1;
        need[static_cast<size_t>(memory_[static_cast<size_t>(i)])] = 1;
      }
  }
  for (int m = 0; m < N; ++m)
    if (need[static_cast<size_t>(m)]) s.update.push_back(m);
  return s;
}

}  // namespace arp::host
