#include "RegionGrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/InputError.hpp"

namespace arp::host {

RegionGrid::RegionGrid(const glm::dvec3& mn, const glm::dvec3& mx, double size, bool cubes, const std::string& source)
    : min_(mn), max_(mx), size_(size), cubes_(cubes) {
  if (!(size > 0) || !std::isfinite(size)) throw InputError(source, "region size", "must be a positive number of metres");
  const glm::dvec3 ext = mx - mn;
  if (!(ext.x > 0 && ext.y > 0 && ext.z > 0)) throw InputError(source, "extent", "the world extent is empty");
  if (size > std::max(ext.x, ext.z))  // cubes taller than the world make one layer
    throw InputError(source, "region size", "is larger than the world (" + std::to_string(std::max(ext.x, ext.z)) + " m)");
  nx_ = std::max(1, static_cast<int>(std::ceil(ext.x / size - 1e-9)));
  nz_ = std::max(1, static_cast<int>(std::ceil(ext.z / size - 1e-9)));
  ny_ = cubes ? std::max(1, static_cast<int>(std::ceil(ext.y / size - 1e-9))) : 1;
  if (static_cast<int64_t>(nx_) * ny_ * nz_ > 1'000'000) throw InputError(source, "region size", "makes more than a million regions");
}

RegionIndex RegionGrid::region_of(const glm::dvec3& p) const {
  auto idx = [this](double v, double lo, int n) { return std::clamp(static_cast<int>(std::floor((v - lo) / size_)), 0, n - 1); };
  return {idx(p.x, min_.x, nx_), cubes_ ? idx(p.y, min_.y, ny_) : 0, idx(p.z, min_.z, nz_)};
}

bool RegionGrid::inside_extent(const glm::dvec3& p) const {
  return p.x >= min_.x && p.x <= max_.x && p.y >= min_.y && p.y <= max_.y && p.z >= min_.z && p.z <= max_.z;
}

double RegionGrid::depth_inside(const glm::dvec3& p, const RegionIndex& r) const {
  const double x0 = min_.x + r.x * size_, z0 = min_.z + r.z * size_;
  double d = std::min({p.x - x0, x0 + size_ - p.x, p.z - z0, z0 + size_ - p.z});
  if (cubes_) {
    const double y0 = min_.y + r.y * size_;
    d = std::min({d, p.y - y0, y0 + size_ - p.y});
  }
  return d;
}

double RegionGrid::depth_past(const glm::dvec3& p, const RegionIndex& from, const RegionIndex& to) const {
  double d = std::numeric_limits<double>::infinity();
  auto axis = [&](int f, int t, double v, double lo) {
    if (f == t) return;
    const double face = lo + (f < t ? t : t + 1) * size_;  // the face of `to` toward `from`
    d = std::min(d, f < t ? v - face : face - v);
  };
  axis(from.x, to.x, p.x, min_.x);
  axis(from.y, to.y, p.y, min_.y);
  axis(from.z, to.z, p.z, min_.z);
  return d;
}

int RegionGrid::ring(const RegionIndex& a, const RegionIndex& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

}  // namespace arp::host
