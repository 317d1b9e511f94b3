#include "CubeFaceRenderer.hpp"

#include "FaceFrustum.hpp"
#include "FaceWords.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace arp::host {

namespace {

struct ClipVertex {
  double u, v, w;
  glm::dvec3 color;
  glm::dvec2 uv;
};

// Signed distance to clip plane k (>= 0 inside): w >= near, w -/+ u >= 0, w -/+ v >= 0.
double inside(const ClipVertex& p, int k, double near) {
  switch (k) {
    case 0: return p.w - near;
    case 1: return p.w - p.u;
    case 2: return p.w + p.u;
    case 3: return p.w - p.v;
    default: return p.w + p.v;
  }
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  return {a.u + (b.u - a.u) * t, a.v + (b.v - a.v) * t, a.w + (b.w - a.w) * t, a.color + (b.color - a.color) * t,
          a.uv + (b.uv - a.uv) * t};
}

// Sutherland-Hodgman against the five planes; `poly` in, clipped polygon out.
void clip(std::vector<ClipVertex>& poly, std::vector<ClipVertex>& tmp, double near) {
  for (int k = 0; k < 5 && !poly.empty(); ++k) {
    tmp.clear();
    for (size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex& p = poly[i];
      const ClipVertex& q = poly[(i + 1) % poly.size()];
      const double dp = inside(p, k, near), dq = inside(q, k, near);
      if (dp >= 0) tmp.push_back(p);
      if ((dp >= 0) != (dq >= 0)) tmp.push_back(lerp(p, q, dp / (dp - dq)));
    }
    poly.swap(tmp);
  }
}

struct Snapped {
  int64_t x, y;  // 1/256 texel
  double inv_w;
  glm::dvec3 color_over_w;
  glm::dvec2 uv_over_w;
};

// Bilinear, repeating; texture row 0 is the image's top (v = 1).
glm::dvec3 sample(const RgbImage& img, glm::dvec2 uv) {
  const double x = (uv.x - std::floor(uv.x)) * img.width - 0.5, y = (1.0 - (uv.y - std::floor(uv.y))) * img.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto at = [&](int ix, int iy) {
    ix = ((ix % img.width) + img.width) % img.width;
    iy = ((iy % img.height) + img.height) % img.height;
    const uint8_t* p = img.px(ix, iy);
    return glm::dvec3(p[0], p[1], p[2]) / 255.0;
  };
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  return (at(ix, iy) * (1 - ax) + at(ix + 1, iy) * ax) * (1 - ay) + (at(ix, iy + 1) * (1 - ax) + at(ix + 1, iy + 1) * ax) * ay;
}

// A centre exactly on edge (dx, dy) belongs to the triangle if the edge is top-left.
bool top_left(int64_t dx, int64_t dy) { return dy > 0 || (dy == 0 && dx < 0); }

// The radial factor sqrt(1 + sc^2 + tc^2) of every texel of a face of size S:
// radial distance = w * factor (the same expression per texel, tabulated).
std::vector<double> radial_factors(int S) {
  std::vector<double> f(static_cast<size_t>(S) * static_cast<size_t>(S));
  for (int y = 0; y < S; ++y)
    for (int x = 0; x < S; ++x) {
      const double sc = 2.0 * (x + 0.5) / S - 1.0, tc = 2.0 * (y + 0.5) / S - 1.0;
      f[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)] = std::sqrt(1.0 + sc * sc + tc * tc);
    }
  return f;
}

void raster(Snapped v0, Snapped v1, Snapped v2, FaceImage& img, const double* radial, int64_t& filled,
            uint32_t object_id, const RgbImage* texture) {
  int64_t area = (v1.x - v0.x) * (v2.y - v0.y) - (v1.y - v0.y) * (v2.x - v0.x);
  if (area == 0) return;
  if (area < 0) {  // one winding for the edge tests; both are drawn
    std::swap(v1, v2);
    area = -area;
  }
  const int S = img.size;
  const int64_t minx = std::max<int64_t>(0, (std::min({v0.x, v1.x, v2.x}) - 128) >> 8);
  const int64_t maxx = std::min<int64_t>(S - 1, (std::max({v0.x, v1.x, v2.x}) + 127) >> 8);
  const int64_t miny = std::max<int64_t>(0, (std::min({v0.y, v1.y, v2.y}) - 128) >> 8);
  const int64_t maxy = std::min<int64_t>(S - 1, (std::max({v0.y, v1.y, v2.y}) + 127) >> 8);
  // Edge e_i is opposite vertex i: e0 = v1 -> v2, e1 = v2 -> v0, e2 = v0 -> v1.
  // e_i(x, y) = ex_i (py - a_i.y) - ey_i (px - a_i.x), exact in 64 bits; one texel
  // to the right subtracts ey_i * 256 (incremental, still exact).
  const Snapped* p[3] = {&v0, &v1, &v2};
  int64_t ex[3], ey[3], step[3];
  int64_t bias[3];  // 0 for a top-left edge (e == 0 is inside), 1 otherwise: inside iff e >= bias
  for (int i = 0; i < 3; ++i) {
    const Snapped& a = *p[(i + 1) % 3];
    const Snapped& b = *p[(i + 2) % 3];
    ex[i] = b.x - a.x;
    ey[i] = b.y - a.y;
    step[i] = ey[i] * 256;
    bias[i] = top_left(ex[i], ey[i]) ? 0 : 1;
  }
  const double inv_area = 1.0 / static_cast<double>(area);
  const bool count_hits = !img.hits.empty();
  for (int64_t y = miny; y <= maxy; ++y) {
    const int64_t py = (y << 8) + 128, px0 = (minx << 8) + 128;
    int64_t e[3];
    for (int i = 0; i < 3; ++i) {
      const Snapped& a = *p[(i + 1) % 3];
      e[i] = ex[i] * (py - a.y) - ey[i] * (px0 - a.x);
    }
    // The row's span: e_i falls by step_i a texel, so e_i >= bias_i holds on an interval of x; their
    // intersection, in exact integers, is the texels the per-texel test would pass, in the same order.
    int64_t lo = 0, hi = maxx - minx;
    for (int i = 0; i < 3; ++i) {
      const int64_t room = e[i] - bias[i];  // inside at offset dx iff room - step_i dx >= 0
      if (step[i] > 0)
        hi = room < 0 ? -1 : std::min(hi, room / step[i]);
      else if (step[i] < 0)
        lo = room >= 0 ? lo : std::max(lo, (-room - step[i] - 1) / -step[i]);
      else if (room < 0)
        hi = -1;
    }
    if (lo > hi) continue;
    for (int i = 0; i < 3; ++i) e[i] -= step[i] * lo;
    const size_t row = static_cast<size_t>(y) * static_cast<size_t>(S);
    for (int64_t x = minx + lo; x <= minx + hi; ++x, e[0] -= step[0], e[1] -= step[1], e[2] -= step[2]) {
      const size_t k = row + static_cast<size_t>(x);
      if (count_hits) ++img.hits[k];
      const double l0 = static_cast<double>(e[0]) * inv_area, l1 = static_cast<double>(e[1]) * inv_area,
                   l2 = static_cast<double>(e[2]) * inv_area;
      const double inv_w = l0 * v0.inv_w + l1 * v1.inv_w + l2 * v2.inv_w;
      const double w = 1.0 / inv_w;
      const double r = w * radial[k];
      if (!(r < img.distance[k])) continue;
      img.distance[k] = r;
      img.color[k] = (l0 * v0.color_over_w + l1 * v1.color_over_w + l2 * v2.color_over_w) * w;
      if (texture) img.color[k] *= sample(*texture, (l0 * v0.uv_over_w + l1 * v1.uv_over_w + l2 * v2.uv_over_w) * w);
      img.object[k] = object_id;
      ++filled;
    }
  }
}

}  // namespace

void FaceImage::reset(int s) {
  const bool count = !hits.empty();
  size = s;
  if (count) hits.assign(static_cast<size_t>(s) * static_cast<size_t>(s), 0);
  distance.assign(static_cast<size_t>(s) * static_cast<size_t>(s), std::numeric_limits<double>::infinity());
  color.assign(distance.size(), glm::dvec3(0.0));
  object.assign(distance.size(), 0);
}

RenderStats CubeFaceRenderer::render_faces(const Scene& scene, const std::vector<size_t>& objects, double t,
                                           const glm::dvec3& eye, int S, std::vector<FaceImage>& faces,
                                           const VertexWarp* warp) const {
  RenderStats st;
  faces.resize(6);
  FaceLists lists = cull_to_faces(scene, objects, t, eye, depth_.near_m, cull_faces_);
  const auto& per_face = lists.per_face;
  const auto& model = lists.model;
  st.objects = lists.objects;
  auto shade = [&](const glm::dvec3& color, const glm::dvec3& n) {
    return color * (light_.ambient + light_.diffuse * std::abs(glm::dot(n, light_.direction)));
  };
  // Each drawn object's vertices in the world (warped) and their shades, once for all the faces it reaches.
  struct Placed {
    std::vector<glm::dvec3> world, shade;  // shade: the lit colour per vertex (Gouraud), empty when flat
  };
  std::vector<Placed> placed(scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    if (!lists.drawn[i]) continue;
    const SceneObject& o = scene.objects[i];
    const Mesh& m = *o.mesh;
    Placed& pl = placed[i];
    pl.world.resize(m.positions.size());
    for (size_t k = 0; k < m.positions.size(); ++k) pl.world[k] = glm::dvec3(model[i] * glm::dvec4(m.positions[k], 1.0));
    if (warp)
      for (auto& w : pl.world) w = (*warp)(i, w);
    if (o.material.smooth && !m.normals.empty()) {
      const glm::dmat3 nmat = glm::inverseTranspose(glm::dmat3(model[i]));
      pl.shade.resize(m.normals.size());
      for (size_t k = 0; k < m.normals.size(); ++k) pl.shade[k] = shade(o.material.color, glm::normalize(nmat * m.normals[k]));
    }
  }
  // Kept per calling thread for the last two face sizes (S^2 square roots, otherwise on every render before
  // the faces are shared out; two: a run's memories and a truth at another size alternate).
  thread_local std::array<std::vector<double>, 2> radial_of_thread;
  const size_t texels = static_cast<size_t>(S) * static_cast<size_t>(S);
  if (radial_of_thread[0].size() != texels) {
    std::swap(radial_of_thread[0], radial_of_thread[1]);
    if (radial_of_thread[0].size() != texels) radial_of_thread[0] = radial_factors(S);
  }
  const std::vector<double>& radial = radial_of_thread[0];
  // The faces are independent: one thread each, the same bits on any count. Their loads differ, so the
  // heaviest (most triangles) go first and a thread takes the next face when it is free.
  std::array<int, 6> order{0, 1, 2, 3, 4, 5};
  std::array<int64_t, 6> load{};
  for (int f = 0; f < 6; ++f)
    for (size_t i : per_face[static_cast<size_t>(f)]) load[static_cast<size_t>(f)] += static_cast<int64_t>(scene.objects[i].mesh->triangles());
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return load[static_cast<size_t>(a)] > load[static_cast<size_t>(b)]; });
  int64_t triangles = 0, filled = 0, rendered = 0;
  // Each face's fill by object, kept apart (the faces run on several threads), summed after.
  std::array<std::vector<int64_t>, 6> fill_of_face;
  if (fill_by_object_)
    for (auto& v : fill_of_face) v.assign(scene.objects.size(), 0);
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : triangles, filled, rendered)
  for (int slot = 0; slot < 6; ++slot) {
    const int f = order[static_cast<size_t>(slot)];
    FaceImage& img = faces[static_cast<size_t>(f)];
    if (per_face[static_cast<size_t>(f)].empty()) {  // nothing reaches it: no storage, nothing drawn
      img.size = S;
      img.distance.clear();
      img.color.clear();
      img.object.clear();
      if (!img.hits.empty()) img.hits.assign(1, 0);
      continue;
    }
    img.reset(S);
    ++rendered;
    const FaceFrame& F = face_frames()[static_cast<size_t>(f)];
    std::vector<ClipVertex> poly, tmp;
    std::vector<Snapped> sn;
    // Each vertex on this face once: its face coordinates, whether it is inside all five clip planes, and
    // then its snapped position. A triangle with three inside vertices needs no clipping (the clipper
    // would return it unchanged) and takes its vertices from here.
    struct OnFace {
      double u, v, w;
      int64_t x, y;
      bool inside;
    };
    std::vector<OnFace> on;
    const double near = depth_.near_m;
    for (size_t i : per_face[static_cast<size_t>(f)]) {
      const SceneObject& o = scene.objects[i];
      const Mesh& m = *o.mesh;
      const int64_t filled_before = filled;  // this thread's own sum (the reduction's private copy)
      triangles += static_cast<int64_t>(m.triangles());  // submitted to this face
      const std::vector<glm::dvec3>& world = placed[i].world;
      const std::vector<glm::dvec3>& vshade = placed[i].shade;
      const bool smooth = !vshade.empty();
      const RgbImage* texture = o.material.texture && !m.uvs.empty() ? o.material.texture.get() : nullptr;
      on.resize(world.size());
      for (size_t k = 0; k < world.size(); ++k) {
        const glm::dvec3 d = world[k] - eye;
        OnFace& p = on[k];
        p.u = glm::dot(d, F.a);
        p.v = glm::dot(d, F.b);
        p.w = glm::dot(d, F.fwd);
        p.inside = p.w - near >= 0 && p.w - p.u >= 0 && p.w + p.u >= 0 && p.w - p.v >= 0 && p.w + p.v >= 0;
        if (p.inside) {
          const double X = (p.u / p.w + 1.0) * 0.5 * S, Y = (p.v / p.w + 1.0) * 0.5 * S;
          p.x = std::llround(X * 256.0);
          p.y = std::llround(Y * 256.0);
        }
      }
      for (size_t t3 = 0; t3 + 2 < m.indices.size(); t3 += 3) {
        const uint32_t id[3] = {m.indices[t3], m.indices[t3 + 1], m.indices[t3 + 2]};
        const glm::dvec3 fn = glm::cross(world[id[1]] - world[id[0]], world[id[2]] - world[id[0]]);
        const double fl = glm::length(fn);
        if (!(fl > 0)) continue;  // degenerate in world space
        const glm::dvec3 flat = smooth ? glm::dvec3(0.0) : shade(o.material.color, fn / fl);
        sn.clear();
        if (on[id[0]].inside && on[id[1]].inside && on[id[2]].inside) {
          for (uint32_t k : id) {
            const OnFace& p = on[k];
            const glm::dvec3 c = smooth ? vshade[k] : flat;
            const glm::dvec2 uv = texture ? m.uvs[k] : glm::dvec2(0.0);
            sn.push_back({p.x, p.y, 1.0 / p.w, c / p.w, uv / p.w});
          }
        } else {
          poly.clear();
          for (uint32_t k : id)
            poly.push_back({on[k].u, on[k].v, on[k].w, smooth ? vshade[k] : flat, texture ? m.uvs[k] : glm::dvec2(0.0)});
          clip(poly, tmp, near);
          if (poly.size() < 3) continue;
          for (const ClipVertex& c : poly) {
            const double X = (c.u / c.w + 1.0) * 0.5 * S, Y = (c.v / c.w + 1.0) * 0.5 * S;
            sn.push_back({std::llround(X * 256.0), std::llround(Y * 256.0), 1.0 / c.w, c.color / c.w, c.uv / c.w});
          }
        }
        for (size_t k = 1; k + 1 < sn.size(); ++k)
          raster(sn[0], sn[k], sn[k + 1], img, radial.data(), filled, static_cast<uint32_t>(i + 1), texture);
      }
      if (fill_by_object_) fill_of_face[static_cast<size_t>(f)][i] += filled - filled_before;
    }
  }
  if (fill_by_object_) {
    st.filled_by_object.assign(scene.objects.size(), 0);
    for (const auto& v : fill_of_face)
      for (size_t i = 0; i < v.size(); ++i) st.filled_by_object[i] += v[i];
  }
  st.triangles = triangles;
  st.texels_filled = filled;
  st.faces_rendered = static_cast<int>(rendered);
  return st;
}

RenderStats CubeFaceRenderer::count(const Scene& scene, const std::vector<size_t>& objects, double t,
                                    const glm::dvec3& eye) const {
  const FaceLists lists = cull_to_faces(scene, objects, t, eye, depth_.near_m, cull_faces_);
  RenderStats st;
  st.objects = lists.objects;
  for (const auto& on_face : lists.per_face) {
    for (size_t i : on_face) st.triangles += static_cast<int64_t>(scene.objects[i].mesh->triangles());
    st.faces_rendered += on_face.empty() ? 0 : 1;
  }
  return st;
}

RenderStats CubeFaceRenderer::render(const Scene& scene, const std::vector<size_t>& objects, double t,
                                     const glm::dvec3& eye, dp::DisplayMemoryBank& bank,
                                     std::vector<FaceImage>* visible, const VertexWarp* warp) const {
  const dp::MemoryFormat& fmt = bank.format();
  // Per thread, reused: at 512^2 the six float faces are ~56 MB, allocated and zeroed afresh on every render otherwise.
  // (Named through references: inside the parallel region a thread_local name is each worker's own.)
  thread_local std::vector<FaceImage> faces_of_thread;
  thread_local std::vector<uint64_t> words_of_thread;
  std::vector<FaceImage>& faces = faces_of_thread;
  std::vector<uint64_t>& words = words_of_thread;
  DepthCode dc = depth_;
  dc.bits = fmt.depth_bits;
  // The faces' words (FaceWords: depth codes and packed colours, vectorised), faces in parallel; then the
  // tiles they touch reserved at once and the faces copied in, in parallel (DisplayMemoryBank::reserve_faces).
  const int S = fmt.face_size;
  const size_t n = static_cast<size_t>(S) * static_cast<size_t>(S);
  words.resize(6 * n);
  const uint64_t empty = fmt.empty_word();
  const dp::Rgb8Packer pack(fmt);
  auto convert = [&](int f) {
    const FaceImage& img = faces[static_cast<size_t>(f)];
    face_words(img.distance.data(), img.color.data(), n, dc, pack, empty, words.data() + static_cast<size_t>(f) * n);
  };
  RenderStats st = render_faces(scene, objects, t, eye, S, faces, warp);
  // (After the drawing, not on the thread that drew each face: conversion costs the same for every face and
  // balances; tied to the drawing it would follow the faces' unequal loads -- measured slower.)
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int f = 0; f < 6; ++f)
    if (!faces[static_cast<size_t>(f)].distance.empty()) convert(f);
  bank.clear_back();
  std::array<const uint64_t*, 6> drawn{};
  for (int f = 0; f < 6; ++f)
    if (!faces[static_cast<size_t>(f)].distance.empty()) drawn[static_cast<size_t>(f)] = words.data() + static_cast<size_t>(f) * n;
  st.texels_written += bank.reserve_faces(drawn, empty);  // tiles allocated here; the faces copied in parallel
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int f = 0; f < 6; ++f)
    if (drawn[static_cast<size_t>(f)]) bank.store_face(f, drawn[static_cast<size_t>(f)], empty);
  bank.commit();
  if (visible) {
    visible->resize(6);
    for (int f = 0; f < 6; ++f) {
      FaceImage& v = (*visible)[static_cast<size_t>(f)];
      v.size = fmt.face_size;
      v.object = std::move(faces[static_cast<size_t>(f)].object);
      v.distance.clear();
      v.color.clear();
    }
  }
  return st;
}

}  // namespace arp::host
