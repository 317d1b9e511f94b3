#include "Primitives.hpp"

#include <cmath>
#include "common/Units.hpp"

namespace arp::host {

namespace {
void add_quad(Mesh& m, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
  const auto base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.uvs.insert(m.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}
}  // namespace

Mesh make_box(const glm::dvec3& size) {
  const glm::dvec3 h = 0.5 * size;
  Mesh m;
  // Each face has its own four corners, so flat normals stay sharp at the edges.
  add_quad(m, {-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z});      // +z
  add_quad(m, {h.x, -h.y, -h.z}, {-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z});  // -z
  add_quad(m, {h.x, -h.y, h.z}, {h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z});      // +x
  add_quad(m, {-h.x, -h.y, -h.z}, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z});  // -x
  add_quad(m, {-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}, {-h.x, h.y, -h.z});      // +y
  add_quad(m, {-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {-h.x, -h.y, h.z});  // -y
  compute_vertex_normals(m);
  return m;
}

Mesh make_quad(double w, double h) {
  Mesh m;
  add_quad(m, {-w / 2, -h / 2, 0}, {w / 2, -h / 2, 0}, {w / 2, h / 2, 0}, {-w / 2, h / 2, 0});
  compute_vertex_normals(m);
  return m;
}

Mesh make_cylinder(double r, double height, int n) {
  Mesh m;
  const double y0 = -height / 2, y1 = height / 2;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * kPi * i / n, a1 = 2 * kPi * (i + 1) / n;
    const glm::dvec3 p0{r * std::cos(a0), 0, -r * std::sin(a0)}, p1{r * std::cos(a1), 0, -r * std::sin(a1)};
    add_quad(m, p0 + glm::dvec3(0, y0, 0), p1 + glm::dvec3(0, y0, 0), p1 + glm::dvec3(0, y1, 0), p0 + glm::dvec3(0, y1, 0));
  }
  m.uvs.clear();  // no texture coordinates on cylinders
  // Caps as fans.
  for (const double y : {y0, y1}) {
    const auto c = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back({0, y, 0});
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * i / n;
      m.positions.push_back({r * std::cos(a), y, -r * std::sin(a)});
    }
    for (int i = 0; i < n; ++i) {
      const uint32_t a = c + 1 + static_cast<uint32_t>(i), b = c + 1 + static_cast<uint32_t>((i + 1) % n);
      if (y > 0) m.indices.insert(m.indices.end(), {c, a, b});
      else m.indices.insert(m.indices.end(), {c, b, a});
    }
  }
  compute_vertex_normals(m);
  return m;
}

Mesh make_sphere(double r, int n) {
  Mesh m;
  const int rings = std::max(2, n / 2);
  for (int j = 0; j <= rings; ++j) {
    const double th = kPi * j / rings;
    for (int i = 0; i <= n; ++i) {
      const double ph = 2 * kPi * i / n;
      m.positions.push_back({r * std::sin(th) * std::cos(ph), r * std::cos(th), -r * std::sin(th) * std::sin(ph)});
    }
  }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<uint32_t>(j * (n + 1) + i), b = a + 1, c = a + static_cast<uint32_t>(n + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
    }
  m.normals.clear();
  for (const auto& p : m.positions) m.normals.push_back(glm::normalize(p));
  return m;
}

}  // namespace arp::host
