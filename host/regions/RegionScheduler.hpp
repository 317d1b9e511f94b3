// Region priority rendering (Chow, Pose & Regan 2005): all objects of a
// region go to one memory, chosen by the region's ring around the user's
// region -- memory = min(ring, memories - 1): the user's own region in
// memory 0, the next ring in memory 1, and so on, everything beyond in the
// slowest memory. Memories update on need: each remembers where the user was
// at its last update and asks for a new one when the user has moved more than
// its threshold distance x = d sqrt(2 (1 - cos theta_t)), d being the nearest
// its regions can be (max(0.25 m, (m - 1/2) region size)). Regions are
// re-assigned only once the user is inside a new region by the margin, and
// then at the slowest memory's next update request, when every memory whose
// regions change updates together -- so walking back and forth across a
// boundary causes no swapping storm.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "RegionGrid.hpp"

namespace arp::host {

// The margin the region trade, the planner and scripts/reproduce-chow2005.sh use with a region size: an eighth of it.
inline double swept_margin_m(double region_size_m) { return region_size_m / 8; }

struct RegionConfig {
  double region_size_m = 4.0;
  bool cubes = false;
  double margin_m = 0.5;
  int memories = 4;
  double threshold_rad = 0.0;  // 0: one display-memory texel
};

class RegionScheduler {
 public:
  // InputError naming `source` for a margin that is negative or not inside a region.
  RegionScheduler(const RegionGrid& grid, const RegionConfig& cfg, int face_size, const glm::dvec3& start,
                  const std::string& source);

  int memory_of_region(int flat_region) const { return memory_[static_cast<size_t>(flat_region)]; }
  // The memory of an object of region `flat_region` whose bound reaches the regions of `span` (lo, hi; none:
  // only its own region): the fastest among them, as it must be right everywhere it reaches.
  int memory_of_object(int flat_region, const std::pair<RegionIndex, RegionIndex>* span) const;
  RegionIndex center() const { return center_; }
  double threshold_distance(int m) const;

  struct Step {
    std::vector<int> update;  // memories to render now
    bool reassigned = false;  // the ring centre moved: the memories in `update` swap together
  };
  // The user at p: which memories must update now. The caller renders them and calls rendered().
  // `can_reassign`: every memory could render now (a re-assignment waits otherwise).
  Step step(const glm::dvec3& p, bool can_reassign = true);
  void rendered(int m, const glm::dvec3& p) { last_[static_cast<size_t>(m)] = p; }
  // Where the user was at memory m's last update.
  const glm::dvec3& last_rendered(int m) const { return last_[static_cast<size_t>(m)]; }
  const RegionGrid& grid() const { return grid_; }
  int64_t reassignments() const { return reassignments_; }

 private:
  void assign_from(const RegionIndex& c);
  const RegionGrid& grid_;
  RegionConfig cfg_;
  double threshold_;
  RegionIndex center_;
  std::vector<int> memory_;
  std::vector<glm::dvec3> last_;
  int64_t reassignments_ = 0;
};

}  // namespace arp::host
