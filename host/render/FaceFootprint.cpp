#include "FaceFootprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "FaceFrustum.hpp"

namespace arp::host {

std::array<glm::dvec3, 2> mesh_box(const Mesh& m) {
  if (m.positions.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
  glm::dvec3 lo = m.positions.front(), hi = lo;
  for (const glm::dvec3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {lo, hi};
}

TexelRect object_face_rect(const SceneObject& o, const std::array<glm::dvec3, 2>& box, double t_s, const glm::dvec3& eye,
                           double margin_m, int face, int S, double near_m) {
  // The world box around the placed model box, grown by the margin, relative to the eye: seen from
  // eye + d with |d_i| <= margin, the object is where it is, less d -- within this box.
  const glm::dmat4 M = o.model_at(t_s);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p{box[c & 1].x, box[(c >> 1) & 1].y, box[(c >> 2) & 1].z};
    const glm::dvec3 w = glm::dvec3(M * glm::dvec4(p, 1.0)) - eye;
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
  lo -= glm::dvec3(margin_m);
  hi += glm::dvec3(margin_m);
  // The box clipped at depth >= near along the face's axis is convex, and so is its image in the face's
  // plane: the hull of its vertices' images -- the corners in front and where the edges cross the near plane.
  const FaceFrame& F = face_frames()[static_cast<size_t>(face)];
  double s0 = std::numeric_limits<double>::infinity(), s1 = -s0, t0 = s0, t1 = -s0;
  auto take = [&](const glm::dvec3& p) {
    const double depth = glm::dot(p, F.fwd);
    const double s = glm::dot(p, F.a) / depth, t = glm::dot(p, F.b) / depth;
    s0 = std::min(s0, s);
    s1 = std::max(s1, s);
    t0 = std::min(t0, t);
    t1 = std::max(t1, t);
  };
  std::array<glm::dvec3, 8> corner;
  std::array<double, 8> depth;
  for (int c = 0; c < 8; ++c) {
    corner[static_cast<size_t>(c)] = {(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
    depth[static_cast<size_t>(c)] = glm::dot(corner[static_cast<size_t>(c)], F.fwd);
    if (depth[static_cast<size_t>(c)] >= near_m) take(corner[static_cast<size_t>(c)]);
  }
  for (int c = 0; c < 8; ++c)
    for (int bit = 1; bit < 8; bit <<= 1) {  // the 12 edges: corners differing in one coordinate
      const int e = c | bit;
      if (e == c) continue;
      const double dc = depth[static_cast<size_t>(c)], de = depth[static_cast<size_t>(e)];
      if ((dc < near_m) == (de < near_m)) continue;
      const double f = (near_m - dc) / (de - dc);
      take(corner[static_cast<size_t>(c)] + f * (corner[static_cast<size_t>(e)] - corner[static_cast<size_t>(c)]));
    }
  TexelRect r;
  if (!(s0 <= s1) || s1 < -1 || s0 > 1 || t1 < -1 || t0 > 1) return r;  // nothing in front, or beside the face
  // Texel centres: sc = 2 (x + 1/2) / S - 1, so x = (sc + 1) S / 2 - 1/2; one texel more each side.
  auto texel = [S](double sc, bool up) {
    const double x = (std::clamp(sc, -1.0, 1.0) + 1.0) * 0.5 * S - 0.5;
    return std::clamp(static_cast<int>(up ? std::ceil(x) + 1 : std::floor(x) - 1), 0, S - 1);
  };
  r.x0 = texel(s0, false);
  r.x1 = texel(s1, true);
  r.y0 = texel(t0, false);
  r.y1 = texel(t1, true);
  return r;
}

double animation_reach_m(const SceneObject& o, double t_s, double dt_s) {
  const Sphere b = o.world_bound(t_s);
  const double spin = std::abs(o.animation.spin_deg_per_s) * (3.14159265358979323846 / 180.0);
  const double path = o.animation.path.size() >= 2 ? o.animation.path_speed : 0.0;
  return (spin * (glm::length(b.center - o.position_at(t_s)) + b.radius) + path) * dt_s;
}

}  // namespace arp::host
