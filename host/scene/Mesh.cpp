#include "Mesh.hpp"

#include <cmath>

#include "common/InputError.hpp"

namespace arp::host {

Sphere bounding_sphere(const Mesh& m) {
  Sphere s;
  if (m.positions.empty()) return s;
  glm::dvec3 lo = m.positions[0], hi = m.positions[0];
  for (const auto& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  s.center = 0.5 * (lo + hi);
  for (const auto& p : m.positions) s.radius = std::max(s.radius, glm::length(p - s.center));
  return s;
}

void check_mesh(const Mesh& m, const std::string& source) {
  if (m.indices.size() % 3 != 0) throw InputError(source, "indices", "not a whole number of triangles");
  if (!m.normals.empty() && m.normals.size() != m.positions.size())
    throw InputError(source, "normals", "must be absent or one per vertex");
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = m.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(source, "vertex " + std::to_string(i), "coordinate is not finite");
    if (std::abs(p.x) > 1e7 || std::abs(p.y) > 1e7 || std::abs(p.z) > 1e7)
      throw InputError(source, "vertex " + std::to_string(i), "coordinate beyond 1e7 (metres): not a plausible model");
  }
  for (size_t i = 0; i < m.normals.size(); ++i) {
    const auto& n = m.normals[i];
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
      throw InputError(source, "normal " + std::to_string(i), "is not finite");
  }
  if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
    throw InputError(source, "texture coordinates", "must be absent or one per vertex");
  for (size_t i = 0; i < m.uvs.size(); ++i)
    if (!std::isfinite(m.uvs[i].x) || !std::isfinite(m.uvs[i].y))
      throw InputError(source, "texture coordinate " + std::to_string(i), "is not finite");
  for (size_t i = 0; i < m.indices.size(); ++i)
    if (m.indices[i] >= m.positions.size())
      throw InputError(source, "triangle " + std::to_string(i / 3),
                       "vertex index " + std::to_string(m.indices[i]) + " is out of range (" +
                           std::to_string(m.positions.size()) + " vertices)");
}

void compute_vertex_normals(Mesh& m) {
  m.normals.assign(m.positions.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const glm::dvec3 n = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    m.normals[a] += n;
    m.normals[b] += n;
    m.normals[c] += n;
  }
  for (auto& n : m.normals) {
    const double l = glm::length(n);
    n = l > 0 ? n / l : glm::dvec3(0, 1, 0);
  }
}

}  // namespace arp::host
