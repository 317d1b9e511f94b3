#include "Segmentation.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <map>
#include <tuple>

namespace arp::host {

namespace {

struct V {
  glm::dvec3 p, n;
  glm::dvec2 uv;
};

bool before(const glm::dvec3& a, const glm::dvec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

// The point of edge (a, b) on plane coordinate[axis] = c, computed from the ends in a fixed order.
V on_plane(const V& a, const V& b, int axis, double c) {
  const V& p = before(a.p, b.p) ? a : b;
  const V& q = before(a.p, b.p) ? b : a;
  const double t = (c - p.p[axis]) / (q.p[axis] - p.p[axis]);
  V v{p.p + (q.p - p.p) * t, p.n + (q.n - p.n) * t, p.uv + (q.uv - p.uv) * t};
  v.p[axis] = c;  // exactly on the plane
  return v;
}

// Splits a convex polygon by the plane: the parts with coordinate <= c and >= c.
void split(const std::vector<V>& poly, int axis, double c, std::vector<V>& lo, std::vector<V>& hi) {
  lo.clear();
  hi.clear();
  for (size_t i = 0; i < poly.size(); ++i) {
    const V& a = poly[i];
    const V& b = poly[(i + 1) % poly.size()];
    const double da = a.p[axis] - c, db = b.p[axis] - c;
    if (da <= 0) lo.push_back(a);
    if (da >= 0) hi.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const V m = on_plane(a, b, axis, c);
      lo.push_back(m);
      hi.push_back(m);
    }
  }
}

double area(const std::vector<V>& poly) {
  glm::dvec3 s(0.0);
  for (size_t i = 1; i + 1 < poly.size(); ++i) s += glm::cross(poly[i].p - poly[0].p, poly[i + 1].p - poly[0].p);
  return 0.5 * glm::length(s);
}

}  // namespace

Segmented segment_scene(const Scene& s, const RegionGrid& grid, bool on) {
  Segmented out;
  out.scene.name = s.name;
  out.scene.extent_min = s.extent_min;
  out.scene.extent_max = s.extent_max;
  out.scene.notes = s.notes;
  for (size_t oi = 0; oi < s.objects.size(); ++oi) {
    const SceneObject& o = s.objects[oi];
    const Sphere wb = o.world_bound(0);
    const RegionIndex lo_r = grid.region_of(wb.center - glm::dvec3(wb.radius)), hi_r = grid.region_of(wb.center + glm::dvec3(wb.radius));
    const bool spans = lo_r != hi_r;
    if (!on || o.animation.animated() || !spans) {
      out.scene.objects.push_back(o);
      out.region.push_back(grid.flat(grid.region_of(wb.center)));
      out.span.push_back({lo_r, hi_r});
      out.source.push_back(oi);
      continue;
    }
    // Cut in world space along every boundary plane the object's bound crosses.
    const glm::dmat4 M = o.model_at(0);
    const glm::dmat3 N = glm::inverseTranspose(glm::dmat3(M));
    const Mesh& m = *o.mesh;
    std::map<int, Mesh> pieces;  // flat region -> mesh
    std::vector<std::vector<V>> work, next;
    std::vector<V> lo, hi;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      std::vector<V> tri;
      for (int k = 0; k < 3; ++k) {
        const uint32_t id = m.indices[t + static_cast<size_t>(k)];
        tri.push_back({glm::dvec3(M * glm::dvec4(m.positions[id], 1.0)),
                       m.normals.empty() ? glm::dvec3(0, 1, 0) : glm::normalize(N * m.normals[id]),
                       m.uvs.empty() ? glm::dvec2(0.0) : m.uvs[id]});
      }
      work.assign(1, tri);
      for (int axis : {0, 1, 2}) {
        if (axis == 1 && !grid.cubes()) continue;
        const int n = axis == 0 ? grid.count_x() : (axis == 1 ? grid.count_y() : grid.count_z());
        for (int b = 1; b < n; ++b) {
          const double c = axis == 0 ? grid.boundary_x(b) : (axis == 1 ? grid.boundary_y(b) : grid.boundary_z(b));
          next.clear();
          for (const auto& poly : work) {
            split(poly, axis, c, lo, hi);
            if (lo.size() >= 3 && area(lo) > 0) next.push_back(lo);
            if (hi.size() >= 3 && area(hi) > 0) next.push_back(hi);
          }
          work.swap(next);
        }
      }
      for (const auto& poly : work) {
        glm::dvec3 c(0.0);
        for (const V& v : poly) c += v.p;
        const int r = grid.flat(grid.region_of(c / static_cast<double>(poly.size())));
        Mesh& piece = pieces[r];
        const auto base = static_cast<uint32_t>(piece.positions.size());
        for (const V& v : poly) {
          piece.positions.push_back(v.p);
          piece.normals.push_back(v.n);
          piece.uvs.push_back(v.uv);
        }
        for (uint32_t k = 1; k + 1 < poly.size(); ++k) piece.indices.insert(piece.indices.end(), {base, base + k, base + k + 1});
      }
    }
    if (m.uvs.empty())
      for (auto& kv : pieces) kv.second.uvs.clear();
    ++out.objects_cut;
    for (auto& [r, piece] : pieces) {
      SceneObject& so = add_object(out.scene, o.name + " [region " + std::to_string(r) + "]",
                                   std::make_shared<Mesh>(std::move(piece)), glm::dvec3(0.0), o.material);
      (void)so;
      out.region.push_back(r);
      out.span.push_back({grid.unflat(r), grid.unflat(r)});
      out.source.push_back(oi);
      ++out.segments;
    }
  }
  return out;
}

}  // namespace arp::host
