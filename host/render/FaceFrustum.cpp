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

FaceLists cull_to_faces(const Scene& scene, const std::vector<size_t>& objects, double t, const glm::dvec3& eye,
                        double near_m, bool cull) {
  FaceLists c;
  c.model.resize(scene.objects.size());
  c.drawn.assign(scene.objects.size(), 0);
  auto one = [&](size_t i) {
    const SceneObject& o = scene.objects[i];
    const Sphere b = o.world_bound(t);
    bool any = false;
    for (int f = 0; f < 6; ++f)
      if (!cull || sphere_meets_face(b.center - eye, b.radius, f, near_m)) {
        c.per_face[static_cast<size_t>(f)].push_back(i);
        any = true;
      }
    if (any) c.model[i] = o.model_at(t);
    c.drawn[i] = any ? 1 : 0;
    c.objects += any ? 1 : 0;
  };
  if (objects.empty())
    for (size_t i = 0; i < scene.objects.size(); ++i) one(i);
  else
    for (size_t i : objects) one(i);
  return c;
}

}  // namespace arp::host
