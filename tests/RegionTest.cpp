// Region priority rendering's foundations: the region grid, the ring rule
// with update-on-need and margin re-assignment (no swapping storm), and
// large-object segmentation that is exactly watertight.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

#include "common/InputError.hpp"
#include "host/priority/HostSimulation.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "host/regions/Segmentation.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/Primitives.hpp"

using namespace arp;
using namespace arp::host;

TEST(RegionGrid, ColumnsCubesRingsAndBadSizes) {
  const RegionGrid g({-10, 0, -10}, {10, 4, 10}, 4.0, false, "test");
  EXPECT_EQ(g.count_x(), 5);
  EXPECT_EQ(g.count_z(), 5);
  EXPECT_EQ(g.count_y(), 1);
  const RegionIndex r = g.region_of({-9, 3, 9.9});
  EXPECT_EQ(r.x, 0);
  EXPECT_EQ(r.z, 4);
  EXPECT_EQ(g.unflat(g.flat(r)), r);
  EXPECT_NEAR(g.depth_inside({-9, 1, 9}, r), 1.0, 1e-12);
  EXPECT_EQ(RegionGrid::ring({0, 0, 0}, {3, 0, -1}), 3);
  EXPECT_EQ(g.region_of({100, 0, 0}).x, 4);  // outside the extent: the nearest edge region
  const RegionGrid c({0, 0, 0}, {8, 8, 8}, 2.0, true, "test");
  EXPECT_EQ(c.count(), 64);
  for (double bad : {0.0, -1.0, 1e9}) EXPECT_THROW(RegionGrid({0, 0, 0}, {8, 8, 8}, bad, false, "bad"), InputError) << bad;
}

TEST(RegionScheduler, RingsUpdateOnNeedAndNoSwappingStormAtABoundary) {
  const RegionGrid g({-20, 0, -20}, {20, 4, 20}, 4.0, false, "test");
  RegionConfig rc;
  rc.threshold_rad = 0.5 * 3.14159265358979 / 180;
  RegionScheduler s(g, rc, 512, {1, 1.6, 1}, "test");
  for (int i = 0; i < g.count(); ++i)
    EXPECT_EQ(s.memory_of_region(i), std::min(RegionGrid::ring(g.unflat(i), s.center()), 3));
  for (int m = 1; m < 4; ++m) EXPECT_GT(s.threshold_distance(m), s.threshold_distance(m - 1));
  // Walk to and fro across the boundary x = 4 (regions are 4 m), never deeper than the 0.5 m margin.
  int64_t updates_slowest = 0;
  for (int k = 0; k < 400; ++k) {
    const double x = 3.7 + 0.6 * std::abs(std::sin(k * 0.05));  // 3.7 .. 4.3
    const auto st = s.step({x, 1.6, 1});
    for (int m : st.update) {
      s.rendered(m, {x, 1.6, 1});
      updates_slowest += m == 3;
    }
  }
  EXPECT_EQ(s.reassignments(), 0);
  // Deeper than the margin: one re-assignment, at the slowest memory's update request, and only one.
  for (int k = 0; k < 400; ++k) {
    const double x = 4.0 + 0.01 * k;  // into the next region up to 8 m
    const auto st = s.step({x, 1.6, 1});
    if (st.reassigned) {
      EXPECT_NE(std::find(st.update.begin(), st.update.end(), 3), st.update.end());
    }
    for (int m : st.update) s.rendered(m, {x, 1.6, 1});
  }
  EXPECT_EQ(s.reassignments(), 1);
  EXPECT_EQ(s.center().x, g.region_of({5, 0, 1}).x);
  EXPECT_THROW(RegionScheduler(g, RegionConfig{4.0, false, 2.5, 4, 0}, 512, {0, 0, 0}, "margin"), InputError);
}

namespace {

// Columns cut along vertical planes only; cubes (tall worlds) along horizontal ones too.
void expect_watertight_cut(bool cubes) {
  SCOPED_TRACE(cubes ? "cubes" : "columns");
  const RegionGrid g({-4, -1, -8}, {4, 3, 0}, 2.0, cubes, "test");
  Scene s;
  Material mt;
  mt.color = {0.8, 0.3, 0.2};
  // A tilted 5 m x 3 m wall and a box, both spanning several regions; a small object that does not.
  SceneObject& wall = add_object(s, "wall", std::make_shared<Mesh>(make_quad(5, 3)), {0.3, 1.2, -4.1}, mt);
  wall.rotation_deg = {23, 7, 3};
  add_object(s, "crate", std::make_shared<Mesh>(make_box({3, 1, 2.5})), {-0.4, 0.4, -6.5}, mt);  // clear of the wall
  add_object(s, "ball", std::make_shared<Mesh>(make_sphere(0.2, 12)), {1, 1, -3}, mt);
  const Segmented seg = segment_scene(s, g, true);
  EXPECT_EQ(seg.objects_cut, cubes ? 3 : 2);  // with cubes the ball straddles y = 1
  EXPECT_GT(seg.segments, 6);
  EXPECT_EQ(seg.scene.objects.size(), seg.region.size());
  // Each piece lies in its region.
  for (size_t i = 0; i < seg.scene.objects.size(); ++i) {
    if (seg.source[i] == 2) continue;
    for (const auto& p : seg.scene.objects[i].mesh->positions) {
      const RegionIndex r = g.unflat(seg.region[i]);
      EXPECT_GE(g.depth_inside(p, r), -1e-9);
    }
  }
  // Rendered, the pieces cover exactly the texels the whole objects cover, each once.
  std::vector<FaceImage> whole(6), cut(6);
  for (auto& f : whole) f.hits.assign(1, 0);
  for (auto& f : cut) f.hits.assign(1, 0);
  const CubeFaceRenderer r;
  r.render_faces(s, {}, 0, {0.1, 1.5, 0.5}, 128, whole);
  r.render_faces(seg.scene, {}, 0, {0.1, 1.5, 0.5}, 128, cut);
  // (A face a piece's bound reaches but no texel of it does is allocated but empty.)
  auto dist = [](const FaceImage& img, size_t k) {
    return img.distance.empty() ? std::numeric_limits<double>::infinity() : img.distance[k];
  };
  auto hits = [](const FaceImage& img, size_t k) { return img.hits.size() > k ? img.hits[k] : 0; };
  // New vertices on a cut are snapped to 1/256 texel like any other, so the
  // outline may move by a texel here and there; inside it, a crack along a
  // cut would leave a texel uncovered, and an overlap would cover one twice.
  int outline_changes = 0, covered = 0;
  for (int f = 0; f < 6; ++f) {
    const auto& a = whole[static_cast<size_t>(f)];
    const auto& b = cut[static_cast<size_t>(f)];
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        const size_t k = static_cast<size_t>(y * 128 + x);
        const bool in_a = std::isfinite(dist(a, k)), in_b = std::isfinite(dist(b, k));
        covered += in_a;
        EXPECT_LE(hits(b, k), std::max<uint16_t>(hits(a, k), 1)) << "face " << f << " texel " << x << "," << y;
        if (in_a == in_b) {
          if (in_a) {
            EXPECT_NEAR(dist(a, k), dist(b, k), 1e-4);  // snapped vertices move depth a hair
          }
          continue;
        }
        ++outline_changes;
        bool interior = x > 0 && y > 0 && x < 127 && y < 127;
        for (int dy = -1; dy <= 1 && interior; ++dy)
          for (int dx = -1; dx <= 1 && interior; ++dx)
            interior = std::isfinite(dist(a, static_cast<size_t>((y + dy) * 128 + x + dx)));
        EXPECT_FALSE(interior && in_a) << "a crack at face " << f << " texel " << x << "," << y;
      }
  }
  EXPECT_GT(covered, 1000);
  EXPECT_LE(outline_changes, covered / 500);
  // Off: nothing is cut; each object goes by its centre.
  const Segmented off = segment_scene(s, g, false);
  EXPECT_EQ(off.objects_cut, 0);
  EXPECT_EQ(off.scene.objects.size(), 3u);
}

}  // namespace

TEST(Segmentation, CutsAlongRegionPlanesWithoutCracksOrDoubleHits) {
  expect_watertight_cut(false);
  expect_watertight_cut(true);
}

TEST(RegionGrid, HysteresisCountsOnlyTheFacesCrossed) {
  const RegionGrid g({0, 0, 0}, {16, 8, 16}, 2.0, true, "test");
  const RegionIndex from = g.region_of({3, 1.6, 3}), to = g.region_of({4.7, 1.6, 3});
  // 0.7 m past x = 4; the eye's 0.4 m from the cube's top face at y = 2 does not count.
  EXPECT_NEAR(g.depth_past({4.7, 1.6, 3}, from, to), 0.7, 1e-12);
  EXPECT_NEAR(g.depth_inside({4.7, 1.6, 3}, to), 0.4, 1e-12);
  EXPECT_NEAR(g.depth_past({3.2, 1.6, 3}, to, from), 0.8, 1e-12);  // back across, going down in x
  EXPECT_EQ(g.depth_past({3, 1, 3}, from, from), std::numeric_limits<double>::infinity());
  // Diagonally into the next region: the lesser of the two crossings.
  EXPECT_NEAR(g.depth_past({4.3, 1.6, 4.9}, from, g.region_of({4.3, 1.6, 4.9})), 0.3, 1e-12);
  // Walking along a region's wall (0.3 m from z = 4) while crossing x: re-assigned
  // once 0.5 m past x = 4, although the wall is nearer than the margin.
  RegionConfig rc;
  rc.margin_m = 0.5;
  rc.threshold_rad = 0.5 * 3.14159265358979 / 180;
  RegionScheduler s(g, rc, 512, {3, 1.6, 3.7}, "test");
  double reassigned_at = -1;
  for (int k = 0; k <= 300 && reassigned_at < 0; ++k) {
    const glm::dvec3 p{3 + 0.01 * k, 1.6, 3.7};
    const auto st = s.step(p);
    if (st.reassigned) reassigned_at = p.x;
    for (int m : st.update) s.rendered(m, p);
  }
  EXPECT_GE(reassigned_at, 4.5 - 1e-9);
  EXPECT_LT(reassigned_at, 6.0);
  // A tall world in cubes: a cube smaller than the eye height still builds layers.
  EXPECT_EQ(g.count_y(), 4);
  EXPECT_EQ(g.region_of({1, 5, 1}).y, 2);
}

// Bad meshes to segment: degenerate triangles (a repeated vertex, three
// collinear points) are dropped, a non-manifold fan (three triangles on one
// edge) is cut triangle by triangle, and a mesh reaching outside the world
// extent goes to the edge regions -- area kept, nothing crashes.
TEST(Segmentation, DegenerateNonManifoldAndOutsideTheWorld) {
  const RegionGrid g({0, 0, 0}, {8, 4, 8}, 2.0, false, "test");
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{1, 1, 1}, {5, 1, 1}, {5, 1, 5},   // a triangle across regions
                     {3, 1, 3}, {3, 1, 3}, {6, 1, 3},   // a repeated vertex
                     {1, 2, 1}, {2, 2, 2}, {3, 2, 3},   // collinear
                     {1, 0.5, 1}, {5, 0.5, 1}, {3, 3, 7}, {3, 0.5, 7}, {-3, 0.5, 12}};  // a fan on one edge, one reaching outside
  mesh->indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 9, 10, 12, 9, 10, 13};
  Scene s;
  s.extent_min = {0, 0, 0};
  s.extent_max = {8, 4, 8};
  Material mt;
  add_object(s, "bad", mesh, {0, 0, 0}, mt);
  const Segmented seg = segment_scene(s, g, true);
  ASSERT_EQ(seg.objects_cut, 1);
  auto tri_area = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { return 0.5 * glm::length(glm::cross(b - a, c - a)); };
  double want = 0, got = 0;
  for (size_t t = 0; t < mesh->indices.size(); t += 3)
    want += tri_area(mesh->positions[mesh->indices[t]], mesh->positions[mesh->indices[t + 1]], mesh->positions[mesh->indices[t + 2]]);
  for (const auto& o : seg.scene.objects) {
    const Mesh& m = *o.mesh;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const double a = tri_area(m.positions[m.indices[t]], m.positions[m.indices[t + 1]], m.positions[m.indices[t + 2]]);
      EXPECT_GT(a, 0.0);  // no degenerate piece survives
      got += a;
    }
  }
  EXPECT_NEAR(got, want, 1e-9 * want);
  EXPECT_GT(seg.segments, 4);
  for (int r : seg.region) EXPECT_LT(r, g.count());
}

TEST(Segmentation, TheGalleryIsCutIntoRegions) {
  const Scene gal = make_gallery({"/nonexistent"});
  const RegionGrid g(gal.extent_min, gal.extent_max, 4.0, false, "gallery");
  const Segmented seg = segment_scene(gal, g, true);
  EXPECT_GT(seg.objects_cut, 10);  // floor, ceiling, walls
  EXPECT_GT(seg.segments, seg.objects_cut);
  size_t tris = 0;
  for (const auto& o : seg.scene.objects) tris += o.mesh->triangles();
  EXPECT_GE(tris, gal.triangles());
}

// Region priority rendering in the host simulation: walking across regions
// re-assigns them, and on screen every segment is in exactly one memory's
// image at every frame.
TEST(RegionScheduler, InTheHostEveryRegionIsInOneMemoryWhileWalkingAcross) {
  const Scene gal = make_gallery({"/nonexistent"});
  const RegionGrid g(gal.extent_min, gal.extent_max, 2.0, false, "gallery");
  Segmented seg = segment_scene(gal, g, true);
  RegionConfig rc;
  rc.region_size_m = 2.0;
  rc.margin_m = 0.3;
  rc.threshold_rad = 1.0 * 3.14159265358979 / 180;
  const WalkPath walk({{0, 1.6, 1.5}, {8, 1.6, 1.5}}, 4.0, "walk");
  RegionScheduler rs(g, rc, 64, walk.position(0), "test");
  dp::MemoryConfig mc;
  mc.face_size = 64;
  dp::DisplayMemorySet mem(mc, 2);
  PriorityConfig pc;
  HostSimulation h(seg.scene, pc, RenderEngine{}, walk, [](double) { return glm::dquat(1, 0, 0, 0); }, mem, 0.064, 60.0);
  h.use_regions(&rs, seg.region);
  h.prime(0);
  for (int f = 0; f < 60; ++f) {
    h.before_frame(f, f / 60.0);
    std::vector<int> seen(seg.scene.objects.size(), 0);
    for (int m = 0; m < 4; ++m)
      for (size_t i : h.shown_objects(m)) ++seen[i];
    for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "segment " << i << " frame " << f;
  }
  EXPECT_GE(rs.reassignments(), 2);  // 4 m/s for a second across 2 m regions
  EXPECT_GT(h.load()[0].updates, 50);  // the user's region: every frame
}
