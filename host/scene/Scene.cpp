#include "Scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace arp::host {

glm::dvec3 SceneObject::position_at(double t) const {
  const auto& a = animation;
  if (a.path.size() < 2 || a.path_speed <= 0) return position;
  double total = 0;
  for (size_t i = 1; i < a.path.size(); ++i) total += glm::length(a.path[i] - a.path[i - 1]);
  if (total <= 0) return a.path.front();
  double d = std::fmod(a.path_speed * t, total);
  if (d < 0) d += total;
  for (size_t i = 1; i < a.path.size(); ++i) {
    const double l = glm::length(a.path[i] - a.path[i - 1]);
    if (d <= l && l > 0) return a.path[i - 1] + (a.path[i] - a.path[i - 1]) * (d / l);
    d -= l;
  }
  return a.path.back();
}

glm::dmat4 SceneObject::model_at(double t) const {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), position_at(t));
  if (animation.spin_deg_per_s != 0)
    m = glm::rotate(m, glm::radians(std::fmod(animation.spin_deg_per_s * t, 360.0)), glm::normalize(animation.spin_axis));
  m = glm::rotate(m, glm::radians(rotation_deg.x), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotation_deg.y), glm::dvec3(1, 0, 0));
  m = glm::rotate(m, glm::radians(rotation_deg.z), glm::dvec3(0, 0, 1));
  return glm::scale(m, scale);
}

Sphere SceneObject::world_bound(double t) const {
  const glm::dmat4 m = model_at(t);
  const double s = std::max({std::abs(scale.x), std::abs(scale.y), std::abs(scale.z)});
  return {glm::dvec3(m * glm::dvec4(model_bound.center, 1.0)), model_bound.radius * s};
}

size_t Scene::triangles() const {
  size_t n = 0;
  for (const auto& o : objects) n += o.mesh ? o.mesh->triangles() : 0;
  return n;
}

SceneObject& add_object(Scene& s, std::string name, std::shared_ptr<const Mesh> mesh, const glm::dvec3& position,
                        const Material& material) {
  SceneObject o;
  o.name = std::move(name);
  o.model_bound = bounding_sphere(*mesh);
  o.mesh = std::move(mesh);
  o.position = position;
  o.material = material;
  s.objects.push_back(std::move(o));
  return s.objects.back();
}

}  // namespace arp::host
