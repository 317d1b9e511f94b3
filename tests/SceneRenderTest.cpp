// Scenes and the cube-face renderer: the renderer's faces follow the address
// generator's convention (a point lands where the pipeline looks for it), the
// fill rule covers shared edges exactly once, clipping and culling hold at
// the extremes, scene files and model imports fail clearly on bad input.
#include <gtest/gtest.h>

#include <thread>

#include <filesystem>
#include <fstream>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "host/cubemap/CubeFaceBasis.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/ModelImport.hpp"
#include "host/scene/Primitives.hpp"
#include "host/scene/SceneFile.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

using namespace arp;
using namespace arp::host;

namespace {

Material plain(const glm::dvec3& color) {
  Material m;
  m.color = color;
  return m;
}

Scene one_object(const Mesh& m, const glm::dvec3& at, const glm::dvec3& color = {1, 0, 0}) {
  Scene s;
  add_object(s, "thing", std::make_shared<Mesh>(m), at, plain(color));
  return s;
}

}  // namespace

TEST(CubeFaceRenderer, APointLandsOnTheTexelThePipelineReadsForItsDirection) {
  const int S = 32;
  const CubeFaceRenderer r;
  const glm::dvec3 eye{1, 2, 3};
  // Texels in the middle, at the edges and in the corners of every face: a
  // small sphere along the texel's own direction (memory_texel_direction, the
  // address generator's convention) must cover that texel.
  for (int f = 0; f < 6; ++f)
    for (const auto& [x, y] : {std::pair{16, 16}, {0, 0}, {S - 1, 0}, {0, S - 1}, {S - 1, S - 1}, {5, 27}}) {
      const Dir3 t = memory_texel_direction(f, x, y, S);
      const glm::dvec3 d = glm::normalize(glm::dvec3(t.x, t.y, t.z));
      const Scene s = one_object(make_sphere(0.05, 16), eye + 10.0 * d);
      std::vector<FaceImage> faces;
      r.render_faces(s, {}, 0, eye, S, faces);
      const double got = faces[static_cast<size_t>(f)].distance[static_cast<size_t>(y * S + x)];
      EXPECT_NEAR(got, 10.0 - 0.05, 0.01) << "face " << f << " texel " << x << "," << y;
    }
}

TEST(CubeFaceRenderer, SharedEdgesAreCoveredExactlyOnce) {
  // A disc of 64 thin triangles fanned around a centre, facing the eye, filling most of -Z.
  Mesh disc;
  disc.positions.push_back({0, 0, 0});
  const int n = 64;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979 * i / n;
    disc.positions.push_back({0.9 * std::cos(a), 0.9 * std::sin(a), 0});
  }
  for (int i = 0; i < n; ++i)
    disc.indices.insert(disc.indices.end(), {0, static_cast<uint32_t>(1 + i), static_cast<uint32_t>(1 + (i + 1) % n)});
  // Plus a grid of 2-triangle quads behind it whose diagonals and edges hit texel centres exactly.
  const Scene s = one_object(disc, {0.013, -0.007, -1});
  std::vector<FaceImage> faces(6);
  for (auto& f : faces) f.hits.assign(1, 0);
  CubeFaceRenderer().render_faces(s, {}, 0, {0, 0, 0}, 128, faces);
  const FaceImage& img = faces[5];
  int covered = 0, twice = 0;
  for (uint16_t h : img.hits) {
    covered += h > 0;
    twice += h > 1;
  }
  EXPECT_EQ(twice, 0);
  // No cracks: every texel centre inside the disc's polygon (shrunk by a texel) is covered.
  int holes = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const double sc = 2.0 * (x + 0.5) / 128 - 1, tc = 2.0 * (y + 0.5) / 128 - 1;
      // -Z: direction (-sc, -tc, -1) hits the plane z = -1 at (-sc, -tc).
      const double px = -sc - 0.013, py = -tc + 0.007;
      if (std::hypot(px, py) < 0.9 * std::cos(3.14159265358979 / n) - 2.0 / 128 && img.hits[static_cast<size_t>(y * 128 + x)] == 0)
        ++holes;
    }
  EXPECT_EQ(holes, 0);
  EXPECT_GT(covered, 3000);

  // A grid of quads whose shared edges pass exactly through texel centres.
  Mesh grid;
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) grid.positions.push_back({-0.5 + i / 8.0, -0.5 + j / 8.0, 0});
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const uint32_t a = static_cast<uint32_t>(j * 9 + i), b = a + 1, c = a + 9, d = c + 1;
      grid.indices.insert(grid.indices.end(), {a, b, d, a, d, c});
    }
  // At distance 1 on -Z with S = 64, texel centres sit at multiples of 1/32 + 1/64: shift so edges hit them.
  const Scene g = one_object(grid, {1.0 / 64, 1.0 / 64, -1});
  std::vector<FaceImage> gf(6);
  for (auto& f : gf) f.hits.assign(1, 0);
  CubeFaceRenderer().render_faces(g, {}, 0, {0, 0, 0}, 64, gf);
  int gtwice = 0, gcovered = 0;
  for (uint16_t h : gf[5].hits) {
    gtwice += h > 1;
    gcovered += h > 0;
  }
  EXPECT_EQ(gtwice, 0);
  EXPECT_EQ(gcovered, 32 * 32);  // a 1 m square at 1 m covers exactly half the face: 32 x 32 centres
}

TEST(CubeFaceRenderer, ClipsAtTheEyeAndCullsFacesNothingReaches) {
  // The eye inside a box: every texel of every face is written, at the right distance.
  const Scene room = one_object(make_box({4, 4, 4}), {0, 0, 0});
  dp::MemoryConfig mc;
  mc.face_size = 16;
  dp::DisplayMemorySet mem(mc, 1);
  const CubeFaceRenderer r;
  const RenderStats st = r.render(room, {}, 0, {0.3, -0.2, 0.1}, mem.bank(0, 0));
  EXPECT_EQ(st.faces_rendered, 6);
  EXPECT_EQ(st.texels_written, 6 * 16 * 16);
  // A triangle through the eye plane and one right at the eye: clipped, no crash, no NaN.
  Mesh m;
  m.positions = {{-1, -1, 1}, {1, -1, -1}, {0, 1, -1}, {0, 0, 0}, {0.001, 0, 0}, {0, 0.001, 0}};
  m.indices = {0, 1, 2, 3, 4, 5};
  std::vector<FaceImage> faces;
  r.render_faces(one_object(m, {0, 0, 0}), {}, 0, {0, 0, 0}, 16, faces);
  for (const auto& f : faces)
    for (double d : f.distance) EXPECT_FALSE(std::isnan(d));
  // One small object straight ahead: only the faces its bound reaches are rendered.
  const RenderStats one = r.render(one_object(make_sphere(0.1, 8), {0, 0, -5}), {}, 0, {0, 0, 0}, mem.bank(0, 0));
  EXPECT_EQ(one.faces_rendered, 1);
  // An empty scene renders nothing and leaves an empty (committed) buffer.
  const RenderStats none = r.render(Scene{}, {}, 0, {0, 0, 0}, mem.bank(0, 0));
  EXPECT_EQ(none.faces_rendered, 0);
  EXPECT_EQ(none.texels_written, 0);
}

TEST(CubeFaceRenderer, ThroughThePipelineTheObjectAheadIsInTheMiddleOfTheView) {
  dp::ArpConfig c;
  c.timing.h_active = 160;
  c.timing.v_active = 120;
  c.memory.face_size = 128;
  c.memory.count = 1;
  dp::DisplayMemorySet mem(c.memory, 2);
  Scene s = one_object(make_box({0.5, 0.5, 0.5}), {0, 1.6, -3}, {1, 0, 0});
  add_object(s, "left wall", std::make_shared<Mesh>(make_box({0.1, 4, 20})), {-3, 1.6, 0}, plain({0, 0, 1}));
  const CubeFaceRenderer r;
  for (int e = 0; e < 2; ++e) {
    r.render(s, {}, 0, {0, 1.6, 0}, mem.bank(e, 0));
    mem.bank(e, 0).vblank();
  }
  HmdFrame f;
  FunctionalModel(c).render(mem, dp::OrientationStream::constant(dp::Quat{}), 0, f);
  EXPECT_GT(f.channel(0, 80, 60, 0), 150u);  // red ahead
  EXPECT_LT(f.channel(0, 80, 60, 2), 60u);
  EXPECT_GT(f.channel(0, 2, 60, 2), 100u);   // blue wall on the left edge
  EXPECT_LT(f.channel(0, 2, 60, 0), 30u);
  EXPECT_EQ(f.at(0, 80, 5), 0u);             // nothing above: background
}

TEST(CubeFaceRenderer, TexturesMapOntoQuadsTheRightWayUp) {
  // A quad facing the eye with a texture whose top half is red and bottom half blue.
  auto tex = std::make_shared<RgbImage>(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      uint8_t* p = tex->px(x, y);
      p[0] = y < 4 ? 255 : 0;
      p[2] = y < 4 ? 0 : 255;
    }
  Scene s;
  Material m = plain({1, 1, 1});
  m.texture = tex;
  add_object(s, "canvas", std::make_shared<Mesh>(make_quad(2, 2)), {0, 0, -2}, m);
  std::vector<FaceImage> faces;
  CubeFaceRenderer().render_faces(s, {}, 0, {0, 0, 0}, 64, faces);
  const FaceImage& f = faces[5];  // -Z: texel row 0 looks up (tc = -1 -> direction y = +1)
  const glm::dvec3 top = f.color[static_cast<size_t>(20 * 64 + 32)], bottom = f.color[static_cast<size_t>(44 * 64 + 32)];
  EXPECT_GT(top.r, 0.2);
  EXPECT_LT(top.b, 0.05);
  EXPECT_GT(bottom.b, 0.2);
  EXPECT_LT(bottom.r, 0.05);
}

TEST(CubeFaceRenderer, IsDeterministic) {
  const Scene g = make_gallery();
  std::vector<FaceImage> a, b;
  const CubeFaceRenderer r;
  r.render_faces(g, {}, 1.25, {3, 1.6, -1}, 64, a);
  r.render_faces(g, {}, 1.25, {3, 1.6, -1}, 64, b);
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(a[static_cast<size_t>(f)].distance, b[static_cast<size_t>(f)].distance);
    EXPECT_TRUE(a[static_cast<size_t>(f)].color == b[static_cast<size_t>(f)].color);
  }
}

// Faces are drawn in parallel: on one thread or two, the same faces, memories, objects and counts,
// bit for bit (a walk's view with clipped and unclipped triangles, textures and both shadings).
TEST(CubeFaceRenderer, AnyThreadCountGivesTheSameBits) {
  const Scene g = make_gallery();
  dp::MemoryConfig mc;
  mc.face_size = 96;
  const dp::MemoryFormat fmt(mc);
  std::vector<FaceImage> faces[2], ids[2];
  dp::DisplayMemoryBank bank0(fmt), bank1(fmt);
  dp::DisplayMemoryBank* banks[2] = {&bank0, &bank1};
  RenderStats st[2], sf[2];
  for (int k = 0; k < 2; ++k) {
    CubeFaceRenderer r;
    r.set_threads(k + 1);
    sf[k] = r.render_faces(g, {}, 2.5, gallery_walk()[3], 96, faces[k]);
    st[k] = r.render(g, {}, 2.5, gallery_walk()[3], *banks[k], &ids[k]);
  }
  EXPECT_EQ(sf[0].texels_filled, sf[1].texels_filled);
  EXPECT_EQ(sf[0].triangles, sf[1].triangles);
  EXPECT_EQ(st[0].texels_written, st[1].texels_written);
  EXPECT_EQ(st[0].texels_filled, st[1].texels_filled);
  EXPECT_EQ(st[0].objects, st[1].objects);
  EXPECT_EQ(st[0].faces_rendered, st[1].faces_rendered);
  EXPECT_GT(st[0].texels_written, 6 * 96 * 96 / 2);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(faces[0][f].distance, faces[1][f].distance) << f;
    EXPECT_TRUE(faces[0][f].color == faces[1][f].color) << f;
    EXPECT_EQ(ids[0][f].object, ids[1][f].object) << f;
    for (int y = 0; y < 96; ++y)
      for (int x = 0; x < 96; ++x)
        ASSERT_EQ(bank0.read_back(static_cast<int>(f), x, y), bank1.read_back(static_cast<int>(f), x, y)) << f << " " << x << " " << y;
  }
}

// Face culling only skips work clipping would discard: with it off every
// object goes to all six faces (6 x the scene's triangles submitted, in closed
// form) and the faces come out the same, texel for texel, object for object.
TEST(CubeFaceRenderer, FaceCullingSavesWorkAndChangesNoTexel) {
  const Scene g = make_gallery();
  std::vector<FaceImage> on, off;
  CubeFaceRenderer r;
  const RenderStats a = r.render_faces(g, {}, 2.5, gallery_walk()[3], 64, on);
  r.set_face_culling(false);
  const RenderStats b = r.render_faces(g, {}, 2.5, gallery_walk()[3], 64, off);
  EXPECT_EQ(b.triangles, 6 * g.triangles());
  EXPECT_LT(2 * a.triangles, b.triangles);  // near objects reach two or three faces, far ones one
  EXPECT_EQ(a.texels_filled, b.texels_filled);
  EXPECT_EQ(b.objects, static_cast<int64_t>(g.objects.size()));
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(on[f].distance, off[f].distance) << f;
    EXPECT_TRUE(on[f].color == off[f].color) << f;
  }
  EXPECT_EQ(r.count(g, {}, 2.5, gallery_walk()[3]).triangles, b.triangles);
}

// The fill by object (what the planner charges the engine for): each object's share of the texels that
// passed the depth test, adding up to them; an object rendered alone fills at least its share (fewer
// occluders drawn before it), and the first object in scene order, drawn first on every face it reaches,
// exactly its share. The same on one thread and on two.
TEST(CubeFaceRenderer, TheFillByObjectIsEachObjectsShare) {
  const Scene g = make_gallery();
  const glm::dvec3 eye = gallery_walk()[3];
  std::vector<FaceImage> faces;
  CubeFaceRenderer r;
  EXPECT_TRUE(r.render_faces(g, {}, 2.5, eye, 64, faces).filled_by_object.empty());  // only when asked for
  r.set_fill_by_object(true);
  r.set_threads(1);
  const RenderStats all = r.render_faces(g, {}, 2.5, eye, 64, faces);
  ASSERT_EQ(all.filled_by_object.size(), g.objects.size());
  int64_t sum = 0;
  for (const int64_t v : all.filled_by_object) sum += v;
  EXPECT_EQ(sum, all.texels_filled);
  int64_t hidden = 0;
  for (size_t i = 0; i < g.objects.size(); ++i) {
    const int64_t alone = r.render_faces(g, {i}, 2.5, eye, 64, faces).texels_filled;
    EXPECT_GE(alone, all.filled_by_object[i]) << g.objects[i].name;
    if (i == 0) {
      EXPECT_EQ(alone, all.filled_by_object[i]) << g.objects[i].name;
    }
    hidden += alone - all.filled_by_object[i];
  }
  EXPECT_GT(hidden, 0);  // some object is behind another drawn before it
  r.set_threads(2);
  EXPECT_EQ(r.render_faces(g, {}, 2.5, eye, 64, faces).filled_by_object, all.filled_by_object);
}

// The renderer's output pinned: the gallery from four points of its walk (0, 2, 4, 6) at 96^2, every memory word,
// every texel's object and the counts, hashed (FNV-1a). The expected value is what the renderer of
// commit 4107c2e computed -- before it was made parallel and incremental -- built on its own from
// that commit with this same function; a change to the renderer's arithmetic shows here.
namespace {
uint64_t gallery_render_hash(int threads) {
  const Scene g = make_gallery();
  dp::MemoryConfig mc;
  mc.face_size = 96;
  dp::DisplayMemoryBank bank{dp::MemoryFormat(mc)};
  uint64_t h = 1469598103934665603ull;
  auto mix = [&](uint64_t v) {
    h ^= v;
    h *= 1099511628211ull;
  };
  CubeFaceRenderer r;
  r.set_threads(threads);
  std::vector<FaceImage> ids;
  const auto walk = gallery_walk();
  for (size_t i = 0; i < walk.size(); i += walk.size() / 3) {
    const RenderStats st = r.render(g, {}, 0.5 + static_cast<double>(i), walk[i], bank, &ids);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) mix(bank.read_back(f, x, y));
    for (const auto& v : ids)
      for (auto o : v.object) mix(static_cast<uint64_t>(o));
    for (const int64_t n : {st.triangles, st.texels_filled, st.texels_written, st.objects}) mix(static_cast<uint64_t>(n));
  }
  return h;
}
}  // namespace

TEST(CubeFaceRenderer, TheGalleryRendersToThePinnedBits) {
  for (const int threads : {1, 2}) EXPECT_EQ(gallery_render_hash(threads), 0x96a4d3071e355c73ull) << threads << " threads";
}

// The renderer keeps per-texel factors of the face sizes it last drew on each thread: drawing at one
// size, then another, then the first again (a run's memories and a truth at another size alternate so)
// gives each size's faces exactly as a thread drawing only that size does.
TEST(CubeFaceRenderer, FaceSizesInTurnOnOneThreadDrawAsEachAlone) {
  const Scene g = make_gallery();
  const glm::dvec3 eye = gallery_walk()[3];
  auto draw = [&](int S) {
    std::vector<FaceImage> faces;
    CubeFaceRenderer r;
    r.set_threads(1);
    r.render_faces(g, {}, 0.5, eye, S, faces);
    std::vector<double> d;
    for (const auto& f : faces) d.insert(d.end(), f.distance.begin(), f.distance.end());
    return d;
  };
  std::vector<double> alone48, alone40, alone32;
  std::thread([&] { alone48 = draw(48); }).join();  // a fresh thread: nothing kept yet
  std::thread([&] { alone40 = draw(40); }).join();
  std::thread([&] { alone32 = draw(32); }).join();
  std::thread([&] {
    for (const int S : {48, 40, 48, 40, 32, 48, 32})
      EXPECT_EQ(draw(S), S == 48 ? alone48 : S == 40 ? alone40 : alone32) << S;
  }).join();
}

TEST(Scenes, GalleryHasRoomsPillarsPicturesAndExhibits) {
  const Scene g = make_gallery();
  int pillars = 0, pictures = 0, exhibits = 0;
  for (const auto& o : g.objects) {
    pillars += o.name.find("pillar") != std::string::npos;
    pictures += o.name.find("picture") != std::string::npos;
    exhibits += o.name.rfind("exhibit", 0) == 0;
  }
  EXPECT_EQ(pillars, 12);
  EXPECT_EQ(pictures, 12);
  EXPECT_EQ(exhibits, 6);
  EXPECT_GT(g.triangles(), 1000u);
  // Without the model packages the gallery still loads, and says what stands in.
  const Scene bare = make_gallery({"/nonexistent"});
  EXPECT_EQ(bare.objects.size(), g.objects.size());
  ASSERT_EQ(bare.notes.size(), 6u);
  EXPECT_NE(bare.notes[0].find("a sphere stands in"), std::string::npos);
  EXPECT_GE(gallery_walk().size(), 5u);
}

TEST(Scenes, SceneFilesLoadAndBadOnesSayWhereAndWhy) {
  arp::test::TempDir d;
  std::ofstream(d.file("ok.json")) << R"({"name": "t", "extent": {"min": [-5,-1,-5], "max": [5,4,5]},
    "objects": [{"name": "b", "box": [1,2,3], "position": [0,1,-2], "color": [1,0,0], "spin": {"axis": [0,1,0], "deg_per_s": 90}},
                {"sphere": 0.5, "segments": 12, "shading": "gouraud", "path": {"points": [[0,1,0],[2,1,0]], "speed": 0.5}},
                {"cylinder": [0.2, 3, 0], "rotation_deg": [0, 90, 0]},
                {"quad": [2, 1, 0]}]})";
  const Scene s = load_scene_file(d.file("ok.json"));
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_TRUE(s.objects[0].animation.animated());
  EXPECT_NEAR(s.objects[1].position_at(2.0).x, 1.0, 1e-12);
  EXPECT_TRUE(s.objects[1].material.smooth);
  auto fails = [&](const std::string& text, const std::string& where) {
    std::ofstream(d.file("bad.json")) << text;
    try {
      load_scene_file(d.file("bad.json"));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  };
  fails(R"({"objects": [{"box": [1,1,1], "colour": [1,0,0]}]})", "objects[0].colour");
  fails(R"({"objects": [{"box": [1,1,1], "sphere": 1}]})", "exactly one of");
  fails(R"({"objects": [{"box": [1,0,1]}]})", "objects[0].box");
  fails(R"({"objects": [{"model": "missing.obj"}]})", "missing.obj");
  fails(R"({"objects": [{"box": [1,1,1], "path": {"points": [[0,0,0]]}}]})", "path.points");
  fails(R"({"objects": [{"box": [1,1,1], "spin": {"axis": [0,0,0]}}]})", "spin.axis");
  fails(R"({"objects": 3})", "objects");
  fails(R"({"objects": [], "extent": {"min": [1,1,1], "max": [0,0,0]}})", "extent");
  fails("{\"objects\": [", "line 1, column 14: JSON syntax error: syntax error while parsing value");
  fails(R"({"objects": [{"cylinder": [1,1,0], "texture": "t.png"}]})", "texture coordinates");
  fails(R"({"objects": [{"quad": [1,1,0], "texture": "missing.png"}]})", "missing.png");
  fails(R"({"base": "cathedral", "objects": []})", "base");
  // An empty scene is a scene.
  std::ofstream(d.file("empty.json")) << R"({"objects": []})";
  EXPECT_TRUE(load_scene_file(d.file("empty.json")).objects.empty());
  // "base": "gallery": the built-in gallery, then the file's objects, named as the file says.
  std::ofstream(d.file("more.json")) << R"({"name": "more", "base": "gallery", "objects": [{"name": "extra", "sphere": 0.1}]})";
  const Scene more = load_scene_file(d.file("more.json"));
  const Scene g = make_gallery();
  ASSERT_EQ(more.objects.size(), g.objects.size() + 1);
  EXPECT_EQ(more.objects.front().name, g.objects.front().name);
  EXPECT_EQ(more.objects.back().name, "extra");
  EXPECT_EQ(more.name, "more");
  EXPECT_EQ(more.extent_max, g.extent_max);
}

TEST(Scenes, BrokenModelsFromAssimpTestModelsAreRefusedClearly) {
  const std::string root = "/usr/share/assimp/models/glTF2/";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels not installed";
  for (const std::string f : {"IndexOutOfRange/IndexOutOfRange.gltf", "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"}) {
    try {
      import_model(root + f);
      ADD_FAILURE() << "accepted " << f;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(f.substr(f.find('/') + 1)), std::string::npos) << e.what();
    }
  }
  const Mesh bunny = import_model("/usr/share/glmark2/models/bunny.obj");
  EXPECT_GT(bunny.triangles(), 1000u);
}
