#include "MagCalibration.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/Units.hpp"

namespace arp::tracker {

namespace {

// The smallest eigenvalue of a symmetric 3x3 matrix (closed form: the roots of its characteristic
// polynomial, all real).
double smallest_eigenvalue(const glm::dmat3& a) {
  const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  if (p1 == 0) return std::min({a[0][0], a[1][1], a[2][2]});
  const double p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  const glm::dmat3 b = (a - q * glm::dmat3(1.0)) * (1.0 / p);
  const double r = std::clamp(glm::determinant(b) / 2.0, -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  return q + 2.0 * p * std::cos(phi + 2.0 * kPi / 3.0);
}

// Solves the 4x4 system m x = v by Gaussian elimination with partial pivoting; false when singular.
bool solve4(double m[4][4], double v[4], double x[4]) {
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(m[r][c]) > std::abs(m[piv][c])) piv = r;
    if (!(std::abs(m[piv][c]) > 1e-300)) return false;
    std::swap(m[c], m[piv]);
    std::swap(v[c], v[piv]);
    for (int r = c + 1; r < 4; ++r) {
      const double f = m[r][c] / m[c][c];
      for (int k = c; k < 4; ++k) m[r][k] -= f * m[c][k];
      v[r] -= f * v[c];
    }
  }
  for (int c = 3; c >= 0; --c) {
    double s = v[c];
    for (int k = c + 1; k < 4; ++k) s -= m[c][k] * x[k];
    x[c] = s / m[c][c];
  }
  return true;
}

}  // namespace

MagCalibration::MagCalibration(const MagCalibrationParams& p) : p_(p) {
  if (p.min_points < 4 || p.max_points < static_cast<size_t>(p.min_points) || !(p.min_separation_deg > 0) || !(p.min_spread > 0) ||
      !(p.max_residual > 0))
    throw std::invalid_argument("magnetometer calibration: min_points >= 4, max_points >= min_points, positive separation, spread and residual");
}

void MagCalibration::add(const glm::dvec3& m) {
  if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.z) || kept_.size() >= p_.max_points) return;
  // Directions from the centre found so far (the origin before the first fit).
  const glm::dvec3 c = offset_fit_;  // (zero before the first fit)
  const glm::dvec3 d = m - c;
  const double dl = glm::length(d);
  if (!(dl > 0)) return;
  const double cos_sep = std::cos(deg_to_rad(p_.min_separation_deg));
  for (const glm::dvec3& k : kept_) {
    const glm::dvec3 e = k - c;
    const double el = glm::length(e);
    if (el > 0 && glm::dot(d, e) / (dl * el) > cos_sep) return;  // too close to a kept one
  }
  kept_.push_back(m);
  if (static_cast<int>(kept_.size()) >= p_.min_points) fit();
}

void MagCalibration::fit() {
  // Least squares of |m|^2 = 2 h.m + k over the kept readings.
  double a[4][4] = {}, v[4] = {};
  for (const glm::dvec3& m : kept_) {
    const double row[4] = {2 * m.x, 2 * m.y, 2 * m.z, 1.0};
    const double y = glm::dot(m, m);
    for (int i = 0; i < 4; ++i) {
      v[i] += row[i] * y;
      for (int j = 0; j < 4; ++j) a[i][j] += row[i] * row[j];
    }
  }
  double x[4];
  if (!solve4(a, v, x)) return;
  const glm::dvec3 h(x[0], x[1], x[2]);
  const double r2 = x[3] + glm::dot(h, h);
  if (!(r2 > 0)) return;
  const double r = std::sqrt(r2);
  double res = 0;
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& m : kept_) {
    const double e = glm::length(m - h) - r;
    res += e * e;
    mean += m;
  }
  const double n = static_cast<double>(kept_.size());
  mean /= n;
  glm::dmat3 cov(0.0);
  for (const glm::dvec3& m : kept_) cov += glm::outerProduct(m - mean, m - mean) * (1.0 / n);
  offset_fit_ = h;
  residual_ = std::sqrt(res / n) / r;
  const bool spread = smallest_eigenvalue(cov) >= (p_.min_spread * r) * (p_.min_spread * r);
  if (spread && residual_ <= p_.max_residual) {  // a trusted fit; a later worse one leaves it applied
    ready_ = true;
    offset_ = h;
    radius_ = r;
  }
}

}  // namespace arp::tracker
