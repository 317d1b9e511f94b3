#include "FaceFrustum.hpp"

#include <cmath>

namespace arp::host {

const std::array<FaceFrame, 6>& face_frames() {
  static const std::array<FaceFrame, 6> f{{
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // +X
      {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // -X
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // +Y
      {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // -Y
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // +Z
      {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // -Z
  }};
  return f;
}

bool sphere_meets_face(const glm::dvec3& c, double r, int f, double near) {
  const FaceFrame& F = face_frames()[static_cast<size_t>(f)];
  const double k = 1.0 / std::sqrt(2.0);
  if (glm::dot(c, F.fwd) < near - r) return false;
  for (const glm::dvec3& side : {F.a, -F.a, F.b, -F.b})
    if (glm::dot(c, (F.fwd - side) * k) < -r) return false;
  return true;
}

}  // namespace arp::host
