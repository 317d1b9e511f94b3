// Chow 2005's regions: the world cut into equal square-based columns (x-z,
// all heights) or, for tall worlds, cubes. Region indices are integers per
// axis from the world extent's minimum corner.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace arp::host {

struct RegionIndex {
  int x = 0, y = 0, z = 0;  // y is always 0 for columns
  bool operator==(const RegionIndex& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const RegionIndex& o) const { return !(*this == o); }
};

class RegionGrid {
 public:
  // InputError naming `source` for a size <= 0, not finite, or larger than the world.
  RegionGrid(const glm::dvec3& extent_min, const glm::dvec3& extent_max, double size, bool cubes,
             const std::string& source);

  double size() const { return size_; }
  bool cubes() const { return cubes_; }
  int count_x() const { return nx_; }
  int count_y() const { return ny_; }
  int count_z() const { return nz_; }
  int count() const { return nx_ * ny_ * nz_; }

  // The region holding p (points outside the extent belong to the nearest edge region).
  RegionIndex region_of(const glm::dvec3& p) const;
  int flat(const RegionIndex& r) const { return (r.y * nz_ + r.z) * nx_ + r.x; }
  RegionIndex unflat(int i) const { return {i % nx_, i / (nx_ * nz_), (i / nx_) % nz_}; }
  bool inside_extent(const glm::dvec3& p) const;
  // How far p is inside region r from its nearest face in x-z (and y for cubes); negative outside.
  double depth_inside(const glm::dvec3& p, const RegionIndex& r) const;
  // How far p has gone into region `to` past the faces it crossed coming from
  // region `from`: the smallest such distance over the axes on which the two
  // differ (faces on other axes do not count, so walking along a wall of the
  // region does not hold back the hysteresis); +infinity when to == from.
  double depth_past(const glm::dvec3& p, const RegionIndex& from, const RegionIndex& to) const;
  // Ring: Chebyshev distance between regions (0: the same region).
  static int ring(const RegionIndex& a, const RegionIndex& b);
  // Boundary plane coordinates: x = boundary_x(i) for i in 1 .. count_x() - 1, likewise z (and y).
  double boundary_x(int i) const { return min_.x + i * size_; }
  double boundary_y(int i) const { return min_.y + i * size_; }
  double boundary_z(int i) const { return min_.z + i * size_; }

 private:
  glm::dvec3 min_, max_;
  double size_;
  bool cubes_;
  int nx_, ny_, nz_;
};

}  // namespace arp::host
