#include "Scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "common/Fingerprint.hpp"

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

int64_t scene_hash(const Scene& s) {
  Fingerprint h;
  auto vec = [&](const glm::dvec3& v) { h.add(v.x).add(v.y).add(v.z); };
  h.add(static_cast<uint64_t>(s.objects.size()));
  for (const SceneObject& o : s.objects) {
    h.add(o.name);
    vec(o.position);
    vec(o.rotation_deg);
    vec(o.scale);
    vec(o.material.color);
    h.add(uint64_t{o.material.smooth}).add(uint64_t{o.material.texture != nullptr});
    if (o.material.texture) {
      h.add(static_cast<uint64_t>(o.material.texture->width)).add(static_cast<uint64_t>(o.material.texture->height));
      for (const uint8_t b : o.material.texture->rgb) h.add(uint64_t{b});
    }
    vec(o.animation.spin_axis);
    h.add(o.animation.spin_deg_per_s).add(o.animation.path_speed).add(static_cast<uint64_t>(o.animation.path.size()));
    for (const auto& p : o.animation.path) vec(p);
    const Mesh& m = *o.mesh;
    h.add(static_cast<uint64_t>(m.positions.size())).add(static_cast<uint64_t>(m.indices.size()));
    for (const auto& p : m.positions) vec(p);
    h.add(static_cast<uint64_t>(m.normals.size())).add(static_cast<uint64_t>(m.uvs.size()));
    for (const auto& v : m.normals) vec(v);
    for (const auto& uv : m.uvs) h.add(uv.x).add(uv.y);
    for (const uint32_t i : m.indices) h.add(uint64_t{i});
  }
  return h.key();
}

}  // namespace arp::host
