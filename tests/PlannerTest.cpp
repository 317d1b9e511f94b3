// arpsim plan (sim/Planner): decisions on small constructed scenes whose right
// answer is known in closed form, the bound on the datapath's error checked by
// the accuracy harness afresh, the plan file read back as any configuration,
// and the priority ladder's keys as the host uses them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <fstream>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "common/PrintfText.hpp"
#include "common/Units.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/PriorityScheduler.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/render/DepthCode.hpp"
#include "host/render/FaceFootprint.hpp"
#include "host/scene/Primitives.hpp"
#include "host/scene/SceneFile.hpp"
#include "reference/accuracy/AccuracyHarness.hpp"
#include "sim/ConfigFile.hpp"
#include "sim/Planner.hpp"
#include "sim/Session.hpp"
#include "sim/TradeMeasure.hpp"

namespace arp::sim {
namespace {

using test::read_text;
using test::run_command;
using test::TempDir;
using arp::test::kArpsim;

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A small display keeps the harness quick; the planner's arithmetic does not depend on the size.
dp::ArpConfig small_display() { return config::apply_overrides({}, {"display.h_active=160", "display.v_active=120"}); }
// The same at 60 Hz, about the default's 59.94 (its porches, 320 x 165 clocks a frame: 3.168 MHz): small_display() is 477 Hz,
// and a run over a walk there takes eight times the frames (under ASan, minutes).
dp::ArpConfig small_display_60hz() {
  return config::apply_overrides(small_display(), {"display.pixel_clock_hz=3168000"});
}

// Object-level priority (--objects-only): the decisions these tests check in closed form are its; region priority
// rendering is weighed by the tests that say so.
PlanRequest request(const std::string& scene, const std::string& walk = "gallery") {
  PlanRequest r;
  r.base = small_display();
  r.memories.scene = scene;
  r.walk = walk;
  r.weigh_regions = false;
  return r;
}

// A row of 0.5 m balls 2 m to the right of a straight walk along -z (row.json, walk.json in `d`): ball i at
// z(i), the walk `length` metres at 1 m/s. Planned at theta_t (the starting widths kept).
PlanRequest ball_row(TempDir& d, int balls, const std::function<double(int)>& z, double length, double threshold_deg) {
  std::string objs;
  for (int i = 0; i < balls; ++i)
    objs += std::string(i ? "," : "") + R"({"name": "b)" + std::to_string(i) + R"(", "sphere": 0.5, "position": [2, 1.6, )" +
            std::to_string(z(i)) + "]}";
  write(d.file("row.json"), R"({"name": "row", "objects": [)" + objs + "]}");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, )" + std::to_string(-length) + "]]}");
  PlanRequest r = request(d.file("row.json"), d.file("walk.json"));
  r.threshold_deg = threshold_deg;
  r.size_widths = false;
  return r;
}

// An undistorted lens of horizontal field F over W pixels: the two pixels either side of the centre
// look tan(F/2)/W either side of the axis, so they are 2 atan(tan(F/2)/W) apart, and the face whose
// centre texel, 2 atan(1/S), is no coarser has S = ceil(W / tan(F/2)).
TEST(Planner, TheFaceSizeIsTheDisplaysResolutionAtTheLensCentre) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  for (const double fov : {90.0, 120.0, 60.0}) {
    PlanRequest r = request(d.file("empty.json"));
    r.base = config::apply_overrides({}, {"lens.k=[1,0,0,0]", "lens.fov_deg=" + std::to_string(fov)});
    r.base.timing.h_active = 640;
    r.size_widths = false;  // the face size alone
    const Plan p = make_plan(r);
    // The centre pair (x = 319, 320 on row 240) is half a pixel below the axis: e = tan(F/2)/W either
    // side and below, directions (-e, -e, -1) and (e, -e, -1), |a x b| = 2e sqrt(1 + e^2), a.b = 1.
    const double e = std::tan(fov * 3.14159265358979323846 / 360.0) / 640.0;
    const double alpha = std::atan(2 * e * std::sqrt(1 + e * e));
    EXPECT_NEAR(p.pixel_angle_centre_rad, alpha, 1e-15);
    const double expected = std::ceil(1.0 / std::tan(alpha / 2) - 1e-9);
    EXPECT_EQ(p.config.memory.face_size, static_cast<int>(expected)) << fov << " degrees";
    EXPECT_NEAR(expected, 640.0 / std::tan(fov * 3.14159265358979323846 / 360.0), 1.0);  // about W / tan(F/2)
    // The corners of a flat panel are finer in angle than its centre: held to them, the face is larger.
    r.resolve = "finest";
    EXPECT_GT(make_plan(r).config.memory.face_size, p.config.memory.face_size);
  }
}

TEST(Planner, AnEmptySceneGivesOneMemoryAndSaysWhy) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  const Plan p = make_plan(request(d.file("empty.json")));
  EXPECT_EQ(p.config.memory.count, 1);
  bool said = false;
  for (const auto& c : p.choices) said = said || c.reason.find("the scene is empty") != std::string::npos;
  EXPECT_TRUE(said);
  for (const bool f : p.faces_reached) EXPECT_FALSE(f);
  EXPECT_EQ(p.config.memory.faces_present(), 6);  // no face is written; the plain cube shows the background
  EXPECT_TRUE(p.config.memory.tiles.empty());       // and keeps its tiles, though none can be drawn on
  EXPECT_EQ(p.tiles.per_memory.at(0), 0);
}

// One object a kilometre ahead, walked toward for ten metres: its image stays within theta_t for
// hundreds of frames throughout, so one memory updated that rarely carries it, and no ladder does
// better; every face but the one it lies on is never reached.
TEST(Planner, OneFarObjectNeedsOneMemoryAndOneFace) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -1000]}]})");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -10]]})");
  PlanRequest r = request(d.file("far.json"), d.file("walk.json"));
  r.threshold_deg = 0.5;
  const Plan p = make_plan(r);
  EXPECT_EQ(p.config.memory.count, 1);
  // Regan & Pose's translational validity (Chow 2005, figure 3), the shortest term here: the user may
  // move sideways by x = d sqrt(2 (1 - cos theta)) before an object at surface distance d shifts by
  // theta; nearest at the walk's end, d = 990 - 0.5 m, at 1 m/s, in this display's frames.
  const double th = 0.5 * 3.14159265358979323846 / 180.0, d_end = 990.0 - 0.5;
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const double need = d_end * std::sqrt(2 * (1 - std::cos(th))) * hz;
  EXPECT_NEAR(p.fastest_need_frames, need, need * 2e-5);  // the tessellated sphere's bound is within millimetres of 0.5 m
  EXPECT_EQ(p.config.memory.update_frames, 1 << static_cast<int>(std::floor(std::log2(need))));  // the largest power of two within it
  const std::array<bool, 6> only_minus_z{false, false, false, false, false, true};
  EXPECT_EQ(p.faces_reached, only_minus_z);
  // The memory keeps that face only: two eyes x one memory x two buffers x one face x S^2 x (24 + 1) bits
  // (one memory: the narrowest depth code, a written flag).
  EXPECT_EQ(p.config.memory.faces, (std::array<int, 6>{0, 0, 0, 0, 0, 1}));
  const int64_t S = p.config.memory.face_size;
  EXPECT_EQ(p.memory_bytes_whole, 2 * 1 * 2 * 1 * S * S * 25 / 8);
  // The ball covers a few of that face's tiles: the memory holds only those, and takes less.
  ASSERT_EQ(p.config.memory.tiles.size(), 1u);
  EXPECT_EQ(p.memory_bytes_planned, p.memory_bytes_tiled);
  EXPECT_LT(p.memory_bytes_planned, p.memory_bytes_whole / 10);
}

// An object that only an eye reaches a face with: seen from the walk's line the ball's bound is 1 cm
// clear of the +X face's frustum (its side plane toward -Z, x + z = 0: clear when (x + z) / sqrt 2 < -r);
// an eye is half the distance between the eyes (3.2 cm) to the side, so the face is kept.
TEST(Planner, AFaceOnlyAnEyeSeesIsKept) {
  TempDir d;
  const double r = 0.5, x = 10.0 - (r + 0.01) * std::sqrt(2.0);  // at z = -10: (x - 10) / sqrt 2 = -(r + 1 cm)
  char obj[200];
  std::snprintf(obj, sizeof obj, R"({"name": "side", "objects": [{"name": "ball", "sphere": %.9f, "position": [%.9f, 1.6, -10]}]})", r, x);
  write(d.file("side.json"), obj);
  write(d.file("walk.json"), R"({"speed": 0.001, "points": [[0, 1.6, 0], [0, 1.6, -0.001]]})");
  const Plan p = make_plan(request(d.file("side.json"), d.file("walk.json")));
  EXPECT_EQ(p.config.memory.faces, (std::array<int, 6>{1, 0, 0, 0, 0, 1}));
}

// Objects near the walk need every frame, objects far away far less: several memories pay.
TEST(Planner, NearAndFarObjectsGetSeveralMemoriesAndLessLoadThanOne) {
  TempDir d;
  PlanRequest r = ball_row(d, 6, [](int i) { return -std::pow(3.0, i + 1); }, 2, 1);  // 3 m .. 729 m ahead
  r.size_widths = true;
  const Plan p = make_plan(r);
  EXPECT_GT(p.config.memory.count, 1);
  // No two of the balls are ever seen in one direction: nothing is composed, and a tie can never be wrong.
  EXPECT_EQ(p.composition.points, p.fill_points);  // (measured, not left at nothing)
  EXPECT_GT(p.composition.points, 0);
  EXPECT_EQ(p.composition.composed, 0);
  EXPECT_EQ(p.config.memory.depth_bits, 1);
  LadderLoad one;
  for (const auto& L : p.ladders)
    if (L.count == 1) one = L;
  ASSERT_EQ(one.count, 1);
  EXPECT_LT(p.planned.triangles_per_s, 0.5 * one.triangles_per_s);
  for (const auto& L : p.ladders)  // the fewest memories that come within the tolerance of the least load
    if (L.count < p.planned.count) {
      EXPECT_GT(L.triangles_per_s, p.best.triangles_per_s * (1 + r.load_tolerance)) << L.count;
    }
}

int64_t tiles_in_text(const std::string& text, int T);  // below

// Standing still, the priority rule puts every object in the slowest memory, whose tiles a plan for a walk
// sized for the objects it holds walking. The host then keeps each object no slower than a memory holding
// its tiles: a run of the plan standing at the walk's start loses nothing, keeping objects faster than the
// rule would (seen losing texels with the host's tile test left out). The plan's memory.assignment, which
// bounds each ball to the memories it had walking, is left out here (it too keeps the nearest balls faster than
// the rule standing: a run with it, below).
TEST(Planner, StandingStillARunKeepsObjectsInMemoriesHoldingTheirTiles) {
  TempDir d;
  PlanRequest r = ball_row(d, 5, [](int i) { return -1.5 * (i + 1); }, 3, 0.5);
  r.tile_pool = false;  // --fixed-tiles (pools: AFullTilePoolMovesObjectsToAFasterMemoryRenderingThen)
  const Plan p = make_plan(r);
  ASSERT_GT(p.config.memory.count, 1);
  ASSERT_FALSE(p.config.memory.tiles.empty());
  nlohmann::json rep[3];
  for (int every = 0; every < 3; ++every) {
    RunSpec spec;
    spec.config = p.config;
    if (every < 2) spec.config.memory.assignment.clear();
    if (every == 1) spec.config.memory.tiles.clear();
    spec.memories.scene = d.file("row.json");
    spec.host.walk = d.file("walk.json");
    spec.host.walk_speed = 0.0;
    spec.frames = 40;
    spec.out.out_dir = d.file("run" + std::to_string(every));
    spec.out.every = 0;
    spec.out.error_every = 0;
    spec.out.report = d.file("r" + std::to_string(every) + ".json");
    Session(spec).run();
    rep[every] = test::load_json(spec.out.report);
  }
  EXPECT_EQ(rep[0]["footprint"]["texels_lost_off_tiles"], 0);
  EXPECT_GT(rep[0]["host"]["object_frames_held_faster_for_tiles"].get<int64_t>(), 0);
  EXPECT_EQ(rep[1]["host"]["object_frames_held_faster_for_tiles"], 0);  // every tile: the rule's own choice
  EXPECT_GT(rep[0]["host"]["triangles_per_s"].get<double>(), rep[1]["host"]["triangles_per_s"].get<double>());
  // With the assignment: the balls the walk never put in the slowest memory are held faster standing.
  std::vector<dp::ObjectAssignment> a;
  std::string why;
  ASSERT_TRUE(dp::object_assignments(p.config.memory, a, why)) << why;
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a[0].name, "b0");
  EXPECT_LT(a[0].slowest, p.config.memory.count - 1);
  EXPECT_GT(rep[2]["host"]["object_frames_held_faster_by_assignment"].get<int64_t>(), 0);
  EXPECT_EQ(rep[2]["footprint"]["texels_lost_off_tiles"], 0);
}

// A tile pool too small for every object the rule puts in a memory: standing still beside the row of balls,
// the rule puts them all in the slower of two memories; with a pool there of a quarter of the tiles they took
// without one (less than one image's), the host moves the balls whose tiles the pool has no room for (beside
// the image shown) to memory 0, which renders at every frame the slower one does, from the first render on:
// nothing is lost, and more is rendered than without the pool (seen losing texels with that move left out,
// and with it left out of the first render), and the balls stay where they were put.
TEST(Planner, AFullTilePoolMovesObjectsToAFasterMemoryRenderingThen) {
  TempDir d;
  ball_row(d, 5, [](int i) { return -1.5 * (i + 1); }, 3, 0.5);
  auto run = [&](const std::vector<int64_t>& pool, const std::string& name) {
    RunSpec spec;
    spec.config = small_display();
    spec.config.memory.count = 2;
    spec.config.memory.face_size = 128;
    spec.config.memory.tile_pool = pool;
    spec.memories.scene = d.file("row.json");
    spec.host.walk = d.file("walk.json");
    spec.host.walk_speed = 0.0;
    spec.frames = 20;
    spec.out.out_dir = d.file(name);
    spec.out.every = 0;
    spec.out.error_every = 0;
    spec.out.report = d.file(name + ".json");
    Session session(spec);
    session.run();
    nlohmann::json j = test::load_json(spec.out.report);
    j["most_at_once_1"] = session.memories().tiles_most_at_once(1);
    return j;
  };
  const nlohmann::json free = run({}, "free");
  const int64_t used = free["most_at_once_1"].get<int64_t>();
  ASSERT_GT(used, 4);
  EXPECT_EQ(free["host"]["memories"][0]["objects_now"], 0);  // standing: every ball in memory 1
  const nlohmann::json held = run({0, used / 4}, "held");
  EXPECT_EQ(held["footprint"]["texels_lost_tile_pool_full"], 0);
  EXPECT_LE(held["most_at_once_1"].get<int64_t>(), used / 4);
  EXPECT_GT(held["host"]["object_frames_kept_faster_for_tile_pool"].get<int64_t>(), 0);
  EXPECT_GT(held["host"]["memories"][0]["objects_now"].get<int64_t>(), 0);
  EXPECT_GT(held["host"]["triangles_per_s"].get<double>(), free["host"]["triangles_per_s"].get<double>());
  EXPECT_EQ(free["host"]["object_frames_kept_faster_for_tile_pool"], 0);
  // And it settles: the balls kept faster stay there, render after render, rather than going back and forth (each
  // ball moves at most once; seen moving 30 times in 20 frames with the joining balls' tiles counted once).
  EXPECT_LE(held["host"]["object_moves"].get<int64_t>(), 5);
}

// An object is drawn only into a memory holding its tiles, whatever way it moves there. Four memories (every
// 1, 2, 4, 8 frames) of which memory 2 holds no tile; a ball the walk leaves behind at 6 m/s needs ever slower
// memories, and goes from memory 1 straight toward 3 at frames where 1 and 2 render but not 3 -- a part-way
// move into memory 2 -- and instead stays faster: nothing is lost (seen losing texels with the move's test
// left out).
TEST(Planner, AnObjectIsDrawnOnlyIntoAMemoryHoldingItsTiles) {
  TempDir d;
  write(d.file("ball.json"), R"({"name": "ball", "objects": [{"name": "b", "sphere": 0.3, "position": [0, 1.6, 0.5]}]})");
  write(d.file("away.json"), R"({"speed": 6, "points": [[0, 1.6, 0], [0, 1.6, -200]]})");
  RunSpec spec;
  spec.config.memory.face_size = 64;
  spec.config.memory.tiles = {"64:*/*/*/*/*/*", "64:*/*/*/*/*/*", "64:-/-/-/-/-/-", "64:*/*/*/*/*/*"};
  spec.config.memory.threshold_deg = 4;
  spec.memories.scene = d.file("ball.json");
  spec.host.walk = d.file("away.json");
  spec.frames = 240;
  spec.out.out_dir = d.file("run");
  spec.out.every = 0;
  spec.out.error_every = 0;
  spec.out.report = d.file("r.json");
  Session(spec).run();
  const nlohmann::json rep = test::load_json(spec.out.report);
  EXPECT_EQ(rep["footprint"]["texels_lost_off_tiles"], 0);
  EXPECT_GT(rep["host"]["object_frames_held_faster_for_tiles"].get<int64_t>(), 0);
  EXPECT_GT(rep["host"]["object_moves"].get<int64_t>(), 1);
}

// A plan's display memory in closed form from its memory.tiles (F faces present, two eyes): a memory listed
// with every tile of them as whole faces (2 buffers x F x S^2 texels), any other as its tiles' 32 x 32 slots
// twice and a tile table of F T^2 entries wide enough to number them and "absent". `whole` and `sparse`
// count the two.
int64_t closed_form_bytes(const Plan& p, int& whole, int& sparse) {
  const int64_t S = p.config.memory.face_size, T = (S + 31) / 32, bits = 24 + p.config.memory.depth_bits;
  const int64_t F = p.config.memory.faces_present();
  whole = sparse = 0;
  int64_t total = 0;
  for (int m = 0; m < p.config.memory.count; ++m) {
    const std::string& t = p.config.memory.tiles[static_cast<size_t>(m)];
    const int64_t n = tiles_in_text(t, static_cast<int>(T));
    if (n == F * T * T) {
      ++whole;
      total += 2 * 2 * F * S * S * bits;
    } else {
      ++sparse;
      total += 2 * (2 * n * 1024 * bits + F * T * T * static_cast<int64_t>(std::floor(std::log2(static_cast<double>(n))) + 1));
    }
  }
  return (total + 7) / 8;
}

// Memory by memory: the row of balls, planned into several memories, inside a sphere of 20 m around the walk
// that every face sees whole. The memory holding the sphere can be drawn on everywhere and keeps whole faces
// (every tile, no table); a memory holding only balls holds their tiles. The plan's hardware figure is the
// two kinds summed (closed form: whole faces, and both buffers of whole slots and a table for the others).
TEST(Planner, AMemoryDrawnOnEverywhereKeepsWholeFaces) {
  TempDir d;
  PlanRequest r = ball_row(d, 6, [](int i) { return -std::pow(3.0, i + 1); }, 2, 1);
  std::string row = read_text(d.file("row.json"));
  row.insert(row.find('[') + 1, R"({"name": "dome", "sphere": 20, "position": [0, 1.6, -1]}, )");
  write(d.file("row.json"), row);
  r.memory_limit_mib = 0;
  r.tile_pool = false;  // --fixed-tiles: the tiles alone (pools: APlannedTilePoolHoldsWhatARunDrawsAndChangesNoTexel)
  const Plan p = make_plan(r);
  const int M = p.config.memory.count;
  ASSERT_GT(M, 1);
  ASSERT_EQ(p.config.memory.tiles.size(), static_cast<size_t>(M));
  EXPECT_EQ(p.config.memory.faces_present(), 6);  // (the dome)
  const int64_t T = (p.config.memory.face_size + 31) / 32;
  for (int m = 0; m < M; ++m) {
    const std::string& t = p.config.memory.tiles[static_cast<size_t>(m)];
    if (t == std::to_string(p.config.memory.face_size) + ":*/*/*/*/*/*") {
      EXPECT_EQ(p.tiles.per_memory[static_cast<size_t>(m)], 6 * T * T) << m;  // the dome's: drawn on everywhere
    } else {
      EXPECT_LT(tiles_in_text(t, static_cast<int>(T)), 6 * T * T / 2) << m;
    }
  }
  int whole = 0, sparse = 0;
  EXPECT_EQ(p.memory_bytes_planned, closed_form_bytes(p, whole, sparse));
  EXPECT_EQ(whole, 1);
  EXPECT_GE(sparse, 1);
  EXPECT_LT(p.memory_bytes_planned, p.memory_bytes_whole);
  EXPECT_LT(p.memory_bytes_planned, p.memory_bytes_tiled);  // less than every memory tile-sparse
  r.tile_sparse = false;  // --whole-faces
  EXPECT_TRUE(make_plan(r).config.memory.tiles.empty());
}

// A memory drawn on nearly everywhere keeps whole faces: four walls 3 m around the walk, 12 m tall (6 m above
// and below the eye), leave only the middle of the +Y and -Y faces -- where a ray goes up or down more than
// twice as steeply as sideways -- unreached, a few tiles; a bank of that many tiles takes more than whole
// faces (2 n 1024 bits a texel and a table against 2 x 6 S^2 bits a texel, worked here), so the plan lists no
// tiles. (Seen failing with every memory made tile-sparse.)
TEST(Planner, AMemoryDrawnOnNearlyEverywhereKeepsWholeFaces) {
  TempDir d;
  write(d.file("walls.json"), R"({"name": "walls", "objects": [
      {"name": "east", "box": [0.1, 12, 6.2], "position": [3, 1.6, 0]},
      {"name": "west", "box": [0.1, 12, 6.2], "position": [-3, 1.6, 0]},
      {"name": "north", "box": [6.2, 12, 0.1], "position": [0, 1.6, -3]},
      {"name": "south", "box": [6.2, 12, 0.1], "position": [0, 1.6, 3]}]})");
  write(d.file("walk.json"), R"({"speed": 0.2, "points": [[0, 1.6, 0.1], [0, 1.6, -0.1]]})");
  PlanRequest r = request(d.file("walls.json"), d.file("walk.json"));
  r.size_widths = false;
  const Plan p = make_plan(r);
  ASSERT_EQ(p.config.memory.faces_present(), 6);
  const int64_t S = p.config.memory.face_size, T = (S + 31) / 32, bits = 24 + p.config.memory.depth_bits;
  int64_t most = 0;  // the most tiles a bank can hold and take less than whole faces
  for (int64_t n = 1; n < 6 * T * T; ++n) {
    const int64_t entry = static_cast<int64_t>(std::ceil(std::log2(static_cast<double>(n) + 1)));
    if (2 * n * 1024 * bits + 6 * T * T * entry < 2 * 6 * S * S * bits) most = n;
  }
  for (size_t m = 0; m < p.tiles.per_memory.size(); ++m) {
    EXPECT_LT(p.tiles.per_memory[m], 6 * T * T) << m;  // not every tile...
    EXPECT_GT(p.tiles.per_memory[m], most) << m;       // ...but too many to take less than whole faces
  }
  EXPECT_TRUE(p.config.memory.tiles.empty());
  EXPECT_EQ(p.memory_bytes_planned, p.memory_bytes_whole);
}

// A plan is for object-level priority: a starting configuration rendering by regions (memory.region_size_m)
// gets a plan rendering by objects, and says why -- its tiles would not be kept to by regions.
TEST(Planner, APlanRendersByObjectsAndSaysSoForAConfigurationByRegions) {
  TempDir d;
  PlanRequest r = ball_row(d, 2, [](int i) { return -3.0 * (i + 1); }, 2, 1);
  r.weigh_regions = true;  // weighed, not taken (the command's default)
  r.base.memory.region_size_m = 4;
  r.base.memory.region_margin_m = 1;
  const Plan p = make_plan(r);
  EXPECT_EQ(p.config.memory.region_size_m, 0.0);
  EXPECT_EQ(p.config.memory.region_margin_m, dp::ArpConfig{}.memory.region_margin_m);
  bool said = false;
  for (const PlanChoice& c : p.choices) said = said || (c.keys.find("memory.region_size_m") == 0 && c.reason.find("4 m is not kept") != std::string::npos);
  EXPECT_TRUE(said);
}

// Region priority rendering weighed: a rail 80 m long 2.5 m beside the walk is one object that object-level
// priority must render every frame (and still not within theta_t: its validity is under a frame); cut along
// region columns, its far pieces go to slower memories -- or, with one memory, update only as the walk goes
// a threshold distance. The plan reports it and, with --take-regions, takes regions, every tile and the base's
// depth code; a run of it renders by
// regions, drawing the pieces and sending the triangles the plan's region weighing said (the run renders the
// pieces as its host simulation schedules them; the plan steps the region rule). (The fill is not compared: a
// piece's is estimated as its object's by its share of the triangles, and the run's depends on the order the
// pieces are drawn in -- 2.3 times less here.)
TEST(Planner, ARailBesideTheWalkIsPlannedByRegions) {
  TempDir d;
  write(d.file("rail.json"), R"({"name": "rail", "objects": [{"name": "rail", "sphere": 1, "scale": [1, 1, 40], "position": [2.5, 1.6, -20]}]})");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  PlanRequest r = request(d.file("rail.json"), d.file("walk.json"));
  r.threshold_deg = 1;
  r.size_widths = false;
  const Plan objects = make_plan(r);
  EXPECT_EQ(objects.config.memory.region_size_m, 0.0);
  EXPECT_TRUE(objects.regions.empty());  // (--objects-only)
  r.weigh_regions = true;
  const Plan weighed = make_plan(r);  // weighed and reported, not taken
  ASSERT_EQ(weighed.regions.size(), 3u);
  EXPECT_EQ(weighed.config.memory.region_size_m, 0.0);
  bool said = false;
  for (const PlanChoice& c : weighed.choices) said = said || c.reason.find("not taken without --take-regions") != std::string::npos;
  EXPECT_TRUE(said);
  r.take_regions = true;
  const Plan p = make_plan(r);
  ASSERT_EQ(p.regions.size(), 3u);
  ASSERT_GT(p.config.memory.region_size_m, 0.0);
  EXPECT_TRUE(p.config.memory.tiles.empty());
  // Its figures and rows: whole faces in closed form (2 eyes x memories x 2 buffers x faces x S^2 x texel bits),
  // the tiles row rewritten.
  const int64_t S = p.config.memory.face_size;
  EXPECT_EQ(p.memory_bytes_planned, int64_t{2} * p.config.memory.count * 2 * p.config.memory.faces_present() * S * S *
                                        (24 + p.config.memory.depth_bits) / 8);
  EXPECT_EQ(p.memory_bytes_whole, p.memory_bytes_planned);
  for (const PlanChoice& c : p.choices) {
    if (c.keys == "memory.tiles") {
      EXPECT_EQ(c.value, "every tile of the faces present");
    }
  }
  const RegionLoad* chosen = nullptr;
  for (const RegionLoad& R : p.regions)
    if (R.size_m == p.config.memory.region_size_m) chosen = &R;
  ASSERT_NE(chosen, nullptr);
  EXPECT_LT(chosen->late_share, p.planned.late_share);  // fewer late than the rail by objects (all of it)
  RunSpec spec;
  spec.config = p.config;
  spec.memories.scene = d.file("rail.json");
  spec.host.walk = d.file("walk.json");
  const double hz = dp::VideoTiming(p.config.timing).refresh_hz();
  spec.frames = static_cast<int64_t>(std::floor(hz));  // the walk: a metre at 1 m/s
  spec.out.out_dir = d.file("run");
  spec.out.every = 0;
  spec.out.error_every = 0;
  spec.out.report = d.file("r.json");
  Session(spec).run();
  const nlohmann::json rep = nlohmann::json::parse(read_text(d.file("r.json")));
  EXPECT_EQ(rep["host"]["mode"], "regions");
  // What the run drew (both eyes) against the plan's region weighing (an eye): pieces, and triangles sent to faces.
  double pieces = 0, sent = 0;
  for (const auto& m : rep["host"]["memories"]) {
    pieces += m["updates"].get<double>() * m["objects_per_update"].get<double>();
    sent += m["triangles_per_s"].get<double>();
  }
  const double seconds = static_cast<double>(spec.frames) / hz;
  EXPECT_NEAR(pieces / seconds, 2 * chosen->pieces_per_s, 0.02 * pieces / seconds);
  EXPECT_NEAR(sent, 2 * chosen->triangles_sent_per_s, 0.05 * sent);
  // Standing, the region rule never updates a memory: not weighed, and said.
  r.walk_speed = 0.0;
  const Plan standing = make_plan(r);
  EXPECT_TRUE(standing.regions.empty());
  EXPECT_EQ(standing.config.memory.region_size_m, 0.0);
  bool said_standing = false;
  for (const PlanChoice& c : standing.choices) said_standing = said_standing || c.reason.find("standing") != std::string::npos;
  EXPECT_TRUE(said_standing);
}

// Regions that would render less but leave more objects outside theta_t than objects do are not taken: two
// balls 3 and 6 m ahead, planned by objects within theta_t; columns of 8 m hold both in a slower memory than
// their validity needs.
TEST(Planner, RegionsThatLeaveMoreObjectsOutsideThetaAreNotTaken) {
  TempDir d;
  PlanRequest r = ball_row(d, 2, [](int i) { return -3.0 * (i + 1); }, 2, 1);
  r.weigh_regions = true;
  r.take_regions = true;
  const Plan p = make_plan(r);
  EXPECT_EQ(p.config.memory.region_size_m, 0.0);
  EXPECT_EQ(p.planned.late_share, 0.0);
  bool why = false;
  for (const PlanChoice& c : p.choices) why = why || c.reason.find("keeps objects within theta_t as well as objects do") != std::string::npos;
  EXPECT_TRUE(why);
  bool less_but_late = false;
  for (const RegionLoad& R : p.regions)
    less_but_late = less_but_late || (R.refused.empty() && R.triangles_per_s < 0.9 * p.planned.triangles_per_s && R.late_share > 0);
  EXPECT_TRUE(less_but_late);
}

// The ladders are held to the display-memory limit (by default the starting configuration's): the row of
// balls, planned into several memories, gets one when the limit is one memory's hardware (2 eyes x 2
// buffers x the faces present x S^2 x (24 + 1) bits), and is refused, naming the least, below it. As whole
// faces (--whole-faces); tile-sparse memories below.
TEST(Planner, TheMemoriesAreHeldToTheMemoryLimit) {
  TempDir d;
  PlanRequest r = ball_row(d, 6, [](int i) { return -std::pow(3.0, i + 1); }, 2, 1);
  r.tile_sparse = false;
  const Plan free = make_plan(r);
  ASSERT_GT(free.config.memory.count, 1);
  EXPECT_EQ(free.memory_limit_bytes, 2 * 4 * 2 * 6 * int64_t{512} * 512 * 40 / 8);  // the default configuration's 120 MiB
  const int64_t S = free.config.memory.face_size, faces = free.config.memory.faces_present();
  const int64_t one = 2 * 1 * 2 * faces * S * S * 25 / 8, two = 2 * 2 * 2 * faces * S * S * 40 / 8;
  for (const int64_t limit : {one, two - 1}) {
    r.memory_limit_mib = static_cast<double>(limit) / 1048576.0;
    const Plan p = make_plan(r);
    EXPECT_EQ(p.config.memory.count, 1) << limit;
    EXPECT_LE(p.memory_bytes_planned, limit);
    EXPECT_GT(p.ladders_over_limit, 0);
  }
  r.memory_limit_mib = static_cast<double>(two) / 1048576.0;
  const Plan at_two = make_plan(r);
  EXPECT_LE(at_two.config.memory.count, 2);
  bool two_weighed = false;  // two memories fit, three do not
  for (const LadderLoad& L : at_two.ladders) {
    two_weighed = two_weighed || L.count == 2;
    EXPECT_LE(L.count, 2);
  }
  EXPECT_TRUE(two_weighed);

  r.memory_limit_mib = static_cast<double>(one - 1) / 1048576.0;
  const InputError e = test::error_of([&] { make_plan(r); });
  EXPECT_NE(std::string(e.what()).find("--memory-limit"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("the least takes"), std::string::npos) << e.what();
  for (const double bad : {-1.0, 1e13}) {
    r.memory_limit_mib = bad;
    EXPECT_NE(std::string(test::error_of([&] { make_plan(r); }).what()).find("--memory-limit"), std::string::npos) << bad;
  }
  r.memory_limit_mib = 0;  // no limit
  EXPECT_EQ(make_plan(r).config.memory.count, free.config.memory.count);
  // By default the limit holds the ladder, not the face size: a starting configuration smaller than one
  // memory at the planned face size limits the plan to the smallest ladder.
  r.memory_limit_mib.reset();
  r.base.memory.face_size = 16;  // its 4 memories: 2 x 4 x 2 x 6 x 16^2 x 40 bits, under one memory at the planned size
  const Plan small = make_plan(r);
  EXPECT_EQ(small.config.memory.count, 1);
  EXPECT_EQ(small.memory_limit_bytes, one);
}

// Where a ladder's memories as whole faces are over the limit, it is weighed as it would be planned: each
// memory holding only the tiles its objects can be drawn on, where that takes less. The row of far balls
// (a few tiles of one face each memory) held to one memory's whole faces gets several tile-sparse memories
// and less host load than one memory; the plan's figure is its tiles in closed form, within the limit; every
// ladder listed whose whole faces are over the limit was bounded and is within it tile-sparse. (Seen failing
// with a ladder weighed as whole faces only.)
TEST(Planner, TheMemoryLimitWeighsTileSparseMemoriesWhereWholeFacesAreOver) {
  TempDir d;
  PlanRequest r = ball_row(d, 6, [](int i) { return -std::pow(3.0, i + 1); }, 2, 1);
  r.tile_sparse = false;
  r.memory_limit_mib = 0;
  const Plan free = make_plan(r);
  const int64_t S = free.config.memory.face_size, faces = free.config.memory.faces_present();
  const int64_t one = 2 * 1 * 2 * faces * S * S * 25 / 8;
  r.memory_limit_mib = static_cast<double>(one) / 1048576.0;
  ASSERT_EQ(make_plan(r).config.memory.count, 1);  // as whole faces
  r.tile_sparse = true;
  r.tile_pool = false;  // --fixed-tiles: the ladder is weighed with fixed tiles, and its figure is theirs
  const Plan p = make_plan(r);
  ASSERT_GT(p.config.memory.count, 1);
  EXPECT_EQ(p.memory_limit_bytes, one);
  EXPECT_LE(p.memory_bytes_planned, one);
  int whole = 0, sparse = 0;
  EXPECT_EQ(p.memory_bytes_planned, closed_form_bytes(p, whole, sparse));
  EXPECT_EQ(whole, 0);
  EXPECT_EQ(sparse, p.config.memory.count);
  LadderLoad single;
  int bounded = 0;
  for (const LadderLoad& L : p.ladders) {
    if (L.count == 1) single = L;
    if (L.memory_bytes_whole <= one) continue;
    ++bounded;
    EXPECT_GT(L.memory_bytes_tiled, 0) << L.count;  // (bounded: within the limit only so)
  }
  EXPECT_GT(bounded, 0);
  ASSERT_EQ(single.count, 1);
  EXPECT_LT(p.planned.triangles_per_s, single.triangles_per_s);
}

// With --weigh-pools, a ladder is weighed against the limit as it would be planned, pools included: at a limit that
// one ladder meets only with its pools, that ladder is weighed with pools and left out with fixed tiles, and by
// default (pools taken after the ladder, which is held to the limit with fixed tiles); the plan's bytes are its
// banks' in closed form -- a pooled bank P slots of 32 x 32 texels and a table for
// each buffer of F x T x T entries numbering P slots (and none), a fixed-tile bank its tiles twice and one table,
// a whole bank its faces twice.
TEST(Planner, TheMemoryLimitWeighsTilePoolsWhereFixedTilesAreOver) {
  TempDir d;
  PlanRequest r = ball_row(d, 6, [](int i) { return -std::pow(3.0, i + 1); }, 2, 1);
  r.memory_limit_mib = 0;
  r.tile_sparse = false;
  const Plan free = make_plan(r);
  r.tile_sparse = true;
  r.weigh_pools = true;
  // Bound them: a limit of one memory's whole faces (as TheMemoryLimitWeighsTileSparseMemoriesWhereWholeFacesAreOver).
  const int64_t S = free.config.memory.face_size, faces = free.config.memory.faces_present(), T = (S + 31) / 32;
  const int64_t one = 2 * 1 * 2 * faces * S * S * 25 / 8;
  r.memory_limit_mib = static_cast<double>(one) / 1048576.0;
  r.tile_pool = false;
  const Plan f1 = make_plan(r);
  r.tile_pool = true;
  const Plan p1 = make_plan(r);
  // A ladder whose pools take less than its fixed tiles and more than nothing: held to exactly its pooled figure.
  const auto key = [](const LadderLoad& L) { return std::to_string(L.count) + "/" + std::to_string(L.update_ratio); };
  const LadderLoad* chosen = nullptr;
  int64_t fixed_bytes = 0;
  for (const LadderLoad& a : p1.ladders)
    for (const LadderLoad& b : f1.ladders)
      if (key(a) == key(b) && a.count > 1 && a.memory_bytes_tiled > 0 && a.memory_bytes_tiled < b.memory_bytes_tiled &&
          (!chosen || a.count > chosen->count)) {
        chosen = &a;
        fixed_bytes = b.memory_bytes_tiled;
      }
  ASSERT_NE(chosen, nullptr) << "no ladder takes less with pools";
  r.memory_limit_mib = static_cast<double>(chosen->memory_bytes_tiled) / 1048576.0;
  r.tile_pool = false;
  const Plan f2 = make_plan(r);
  r.tile_pool = true;
  r.weigh_pools = false;
  const Plan d2 = make_plan(r);
  r.weigh_pools = true;
  const Plan p2 = make_plan(r);
  const auto weighed = [&](const Plan& p) {
    for (const LadderLoad& L : p.ladders)
      if (key(L) == key(*chosen)) return true;
    return false;
  };
  EXPECT_TRUE(weighed(p2)) << key(*chosen) << " at " << chosen->memory_bytes_tiled << " bytes";
  EXPECT_FALSE(weighed(f2)) << key(*chosen) << ": " << fixed_bytes << " bytes with fixed tiles";
  EXPECT_FALSE(weighed(d2)) << key(*chosen) << ": by default weighed with fixed tiles";
  ASSERT_NE(key(p2.planned), key(d2.planned));  // (so the command's plan below tells the flag's from the default's)
  // The command's --weigh-pools gives the library's plan.
  char limit[64];
  std::snprintf(limit, sizeof limit, "%.17g", *r.memory_limit_mib);
  const auto o = run_command(kArpsim + " plan -q --scene " + d.file("row.json") + " --walk " + d.file("walk.json") +
                             " --threshold-deg 1 --keep-widths --objects-only --set display.h_active=160 --set display.v_active=120"
                             " --memory-limit " + limit + " --weigh-pools -o " + d.file("weighed.json"));
  ASSERT_EQ(o.status, 0) << o.output;
  const dp::ArpConfig c = config::load_file(d.file("weighed.json"));
  EXPECT_EQ(c.memory.count, p2.config.memory.count);
  EXPECT_EQ(c.memory.tile_pool, p2.config.memory.tile_pool);
  EXPECT_EQ(c.memory.update_ratio, p2.config.memory.update_ratio);
  EXPECT_LE(p2.memory_bytes_planned, p2.memory_limit_bytes);
  // The planned bytes in closed form.
  const int64_t bits = 24 + p2.config.memory.depth_bits;
  std::vector<dp::TileMap> maps;
  std::string why;
  ASSERT_TRUE(dp::tile_maps(p2.config.memory, maps, why)) << why;
  const auto entry_bits = [](int64_t n) { return static_cast<int64_t>(std::floor(std::log2(static_cast<double>(n)))) + 1; };
  int64_t total = 0;
  int pools = 0;
  for (int m = 0; m < p2.config.memory.count; ++m) {
    const int64_t slots = p2.config.memory.pool_slots(m);
    const int64_t held = maps.empty() ? faces * T * T : maps[static_cast<size_t>(m)].tiles();
    if (slots > 0) {
      ++pools;
      total += 2 * (slots * 1024 * bits + 2 * faces * T * T * entry_bits(slots));
    } else if (held < faces * T * T) {
      total += 2 * (2 * held * 1024 * bits + faces * T * T * entry_bits(held));
    } else {
      total += 2 * 2 * faces * S * S * bits;
    }
  }
  EXPECT_GT(pools, 0);
  EXPECT_EQ(p2.memory_bytes_planned, (total + 7) / 8);
}

// A depth code wider than the memory limit allows is not taken, whatever --depth-error asks. A ball 10 m
// ahead spinning (a fast memory) inside a still one 0.1 mm larger (a slow memory, nearer everywhere): 16-bit
// codes (steps of 1.5 mm there) tie, 32-bit ones do not. With no wrong texel allowed the plan needs more than
// 16 bits; held to two memories at 16 bits it is refused, naming the limit; with no limit it is wider.
TEST(Planner, ADepthCodeIsNeverWiderThanTheMemoryLimitAllows) {
  TempDir d;
  write(d.file("balls.json"), R"({"name": "balls", "objects": [
      {"name": "spinning", "sphere": 1.0, "position": [0, 1.6, -10], "spin": {"deg_per_s": 30}},
      {"name": "still", "sphere": 1.0001, "position": [0, 1.6, -10]}]})");
  write(d.file("walk.json"), R"({"speed": 0.1, "points": [[0, 1.6, 0], [0, 1.6, -0.5]]})");
  PlanRequest r = request(d.file("balls.json"), d.file("walk.json"));
  r.threshold_deg = 1;
  r.size_widths = false;
  r.depth_error = 0;
  r.memory_limit_mib = 0;
  r.tile_sparse = false;  // (the limit below in closed form: whole faces)
  const Plan wide = make_plan(r);
  ASSERT_EQ(wide.config.memory.count, 2);
  ASSERT_GT(wide.composition.wrong[16], 0);
  EXPECT_GT(wide.config.memory.depth_bits, 16);
  const int64_t S = wide.config.memory.face_size, faces = wide.config.memory.faces_present();
  r.memory_limit_mib = static_cast<double>(2 * 2 * 2 * faces * S * S * 40 / 8) / 1048576.0;
  const InputError e = test::error_of([&] { make_plan(r); });
  EXPECT_NE(std::string(e.what()).find("--memory-limit"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("at 16 bits"), std::string::npos) << e.what();
}

// Two memories composed by depth code, in closed form. A 3 m square 2 m ahead of the eye in memory 1, in
// front of a wall 2.2 m ahead in memory 0: along any ray the wall is 1.1x as far, so the codes of a
// logarithmic depth code with M = 2^w - 2 steps over ln(far / near) are ln(1.1) M / ln(far / near) steps
// apart: at least one step -- never a tie -- from the width where that reaches 1 (7 bits over 0.05 ..
// 1000 m); below it the square's texels can tie, and a tie goes to memory 0, the wall, wrongly; at 1 or
// 2 bits every code is the same (0 and 1 of 0 .. 2). With the memories the other way round every tie is
// won by the nearer square: right at every width.
TEST(CompositionDepth, TiesBelowTheWidthTheDistanceRatioNeedsAndOnlyWhereTheNearerIsInTheHigherMemory) {
  host::Scene s;
  host::Material m;
  host::add_object(s, "square", std::make_shared<host::Mesh>(host::make_quad(3, 3)), {0, 0, -2}, m);
  host::add_object(s, "wall", std::make_shared<host::Mesh>(host::make_quad(12, 12)), {0, 0, -2.2}, m);
  const host::DepthCode dc;
  const double steps_per_code = std::log(1.1) / std::log(dc.far_m / dc.near_m);
  int needed = 1;
  while (((int64_t{1} << needed) - 2) * steps_per_code < 1) ++needed;
  ASSERT_EQ(needed, 7);
  // The square's texels, counted from a render of it alone: where both memories hold a surface.
  std::vector<host::FaceImage> alone;
  host::CubeFaceRenderer().render_faces(s, {0}, 0.0, {0, 0, 0}, 128, alone);
  int64_t square = 0;
  for (const auto& f : alone)
    for (const double d : f.distance) square += std::isfinite(d) ? 1 : 0;
  ASSERT_GT(square, 1000);

  CompositionDepth wrong_way;
  add_composition_depth(s, {1, 0}, 2, 0.0, {0, 0, 0}, 128, wrong_way);
  EXPECT_EQ(wrong_way.points, 1);
  EXPECT_EQ(wrong_way.composed, square);
  EXPECT_EQ(wrong_way.wrong[1], square);
  EXPECT_EQ(wrong_way.wrong[2], square);
  EXPECT_GT(wrong_way.wrong[needed - 1], 0);
  for (int w = needed; w <= CompositionDepth::kMaxBits; ++w) EXPECT_EQ(wrong_way.wrong[static_cast<size_t>(w)], 0) << w;
  EXPECT_EQ(wrong_way.narrowest(1, 32, 0.0), needed);
  EXPECT_EQ(wrong_way.narrowest(1, 32, 1.0), 1);
  EXPECT_EQ(wrong_way.narrowest(1, needed - 1, 0.0), 0) << "no width up to the top meets the bound";

  CompositionDepth right_way;
  add_composition_depth(s, {0, 1}, 2, 0.0, {0, 0, 0}, 128, right_way);
  EXPECT_EQ(right_way.composed, square);
  for (int w = 1; w <= CompositionDepth::kMaxBits; ++w) EXPECT_EQ(right_way.wrong[static_cast<size_t>(w)], 0) << w;
  EXPECT_EQ(right_way.narrowest(1, 32, 0.0), 1);
}

// A loose bound gives narrower widths than a tight one, and the harness, run afresh on the plan,
// measures within the bound.
TEST(Planner, ALooserBoundGivesNarrowerWidthsWithinIt) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  PlanRequest r = request(d.file("empty.json"));
  r.texel_error = 2.0;
  const Plan loose = make_plan(r);
  r.texel_error = 0.1;
  const Plan tight = make_plan(r);
  const auto& a = loose.config.widths;
  const auto& b = tight.config.widths;
  EXPECT_LT(a.vec_frac + a.mat_frac + a.rot_frac + a.quot_frac + a.recip_frac_bits,
            b.vec_frac + b.mat_frac + b.rot_frac + b.quot_frac + b.recip_frac_bits);
  for (const Plan* p : {&loose, &tight}) {
    accuracy::Options o = accuracy_options(TradeScale{true});
    o.color_orientations = 0;
    o.aligned = false;
    o.seed = 7;  // other samples than the planner's
    const double err = accuracy::run(p->config, o).overall.max_error;
    EXPECT_LE(err, p->texel_error_bound * 1.25) << "bound " << p->texel_error_bound;
  }
}

TEST(Planner, APlanNeedsAMotion) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  const InputError e = test::error_of([&] { make_plan(request(d.file("empty.json"), "")); });
  EXPECT_EQ(e.source(), "--walk");
}

// Nothing moves (standing, static objects): memory 0 is updated once in the motion, at least once a second.
TEST(Planner, WhatNeverChangesIsUpdatedOnceASecondAtMost) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -10]}]})");
  PlanRequest r = request(d.file("far.json"));
  r.walk_speed = 0.0;
  r.size_widths = false;
  const Plan p = make_plan(r);
  EXPECT_FALSE(std::isfinite(p.fastest_need_frames));
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  EXPECT_EQ(p.config.memory.update_frames, 1 << static_cast<int>(std::floor(std::log2(hz))));
  EXPECT_EQ(p.config.memory.count, 1);
}

// An engine whose only cost is its triangles (no set-up, the fill made negligible), at this rate; the
// widths kept.
void triangles_alone(PlanRequest& r, double triangles_per_s) {
  r.size_widths = false;
  r.base.host.object_setup_s = 0;
  r.base.host.texels_per_s = 1e15;
  r.base.host.triangles_per_s = triangles_per_s;
}

// The rendering engine (host.*) must carry the ladder. Standing still before one ball of T triangles,
// the least an engine can be asked is the ball drawn for each of two eyes once a second (the slowest
// update when the motion spans no time: a second's frames): 2 T / rate of each second. At T triangles a
// second that is 2 s: refused, naming it and that no theta_t helps. At 4 T the ladder the plan takes,
// one memory every 2^floor(log2 hz) frames, keeps it busy (2 T / 4 T) hz / 2^floor(log2 hz) of a second.
TEST(Planner, AnEngineThatCannotCarryTheSceneIsRefusedNamingTheLeastLoad) {
  TempDir d;
  write(d.file("ball.json"), R"({"name": "ball", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -10]}]})");
  const double T = static_cast<double>(host::load_scene_file(d.file("ball.json")).objects.at(0).mesh->triangles());
  PlanRequest r = request(d.file("ball.json"));
  r.walk_speed = 0.0;
  triangles_alone(r, T);
  const InputError e = test::error_of([&] { make_plan(r); });
  EXPECT_EQ(e.place(), "host.triangles_per_s") << e.what();
  EXPECT_NE(e.reason().find("no theta_t helps"), std::string::npos) << e.what();
  EXPECT_NE(e.reason().find("it needs 2 s a second"), std::string::npos) << e.what();
  r.base.host.triangles_per_s = 4 * T;
  const Plan p = make_plan(r);
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const double first = std::exp2(std::floor(std::log2(hz)));
  EXPECT_EQ(p.config.memory.update_frames, static_cast<int>(first));
  EXPECT_NEAR(p.planned.engine_busy, 0.5 * hz / first, 1e-9);
}

// The engine's triangles count once for every face an object reaches, as the renderers send them: a ball
// seen along a cube corner's diagonal reaches three faces (+X, +Y, -Z), and costs three times the ball
// seen along an axis (one face, the test above).
TEST(Planner, AnObjectOnACornerDiagonalCostsTheEngineThreeFaces) {
  TempDir d;
  write(d.file("walk.json"), R"({"speed": 0, "points": [[0, 1.6, 0], [1, 1.6, 0]]})");
  write(d.file("corner.json"),
        R"({"name": "corner", "objects": [{"name": "ball", "sphere": 0.5, "position": [6, 7.6, -6]}]})");
  const double T = static_cast<double>(host::load_scene_file(d.file("corner.json")).objects.at(0).mesh->triangles());
  PlanRequest r = request(d.file("corner.json"), d.file("walk.json"));
  triangles_alone(r, T);
  const InputError e = test::error_of([&] { make_plan(r); });
  EXPECT_EQ(e.place(), "host.triangles_per_s") << e.what();
  EXPECT_NE(e.reason().find("it needs 6 s a second"), std::string::npos) << e.what();  // 2 eyes x 3 faces x T / T
  r.base.host.triangles_per_s = 16 * T;
  const Plan p = make_plan(r);
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const double first = std::exp2(std::floor(std::log2(hz)));
  ASSERT_EQ(p.config.memory.update_frames, static_cast<int>(first));
  EXPECT_NEAR(p.planned.engine_busy, 2.0 * 3.0 / 16.0 * hz / first, 1e-9);
}

// The engine a plan needs, in closed form. One ball far ahead of a short walk, always in the -Z face of both eyes:
// each update of its one memory, every P frames, costs the engine 2 eyes x T triangles / rate (no set-up, the fill
// made negligible), and must be done within P frames for its image to be shown before the memory is due again. So
// the least engine is 2 T hz / (P rate) times this one. (With one memory that is its busy share: an engine any
// slower is refused, AnEngineThatCannotCarryTheScene... above.) The write port that stores the needed engine's fill
// (its rate times 1e15 texels/s here) at 100 MHz is that over the clock, or, wider than the key allows, the widest,
// and the reason says so.
TEST(Planner, TheLeastEngineRendersEachUpdateWithinItsPeriod) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -40]}]})");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  const double T = static_cast<double>(host::load_scene_file(d.file("far.json")).objects.at(0).mesh->triangles());
  PlanRequest r = request(d.file("far.json"), d.file("walk.json"));
  triangles_alone(r, 1000 * T);
  const Plan p = make_plan(r);
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const double P = p.config.memory.update_frames;
  ASSERT_EQ(p.config.memory.count, 1);
  ASSERT_LT(P, p.motion_s * hz);  // due at least twice
  EXPECT_NEAR(p.planned_need.scale, 2 * T * hz / (P * 1000 * T), 1e-5 * p.planned_need.scale);
  EXPECT_EQ(p.planned_need.skipped, 0);
  EXPECT_NEAR(p.planned_need.longest_render_s, 2 * T / (1000 * T), 1e-9);
  EXPECT_EQ(p.config.timed.host_texels_per_cycle, static_cast<int>(std::ceil(p.planned_need.scale * 1e15 / 1e8)));
  // Twice as slow as that, it needs half of itself; the port for the needed engine's 5e14 texels/s would take 5e6
  // texels a clock at 100 MHz, over the key's range.
  triangles_alone(r, T * 2 * hz / P / 0.5);
  const Plan half = make_plan(r);
  EXPECT_NEAR(half.planned_need.scale, 0.5, 1e-5);
  EXPECT_EQ(half.config.timed.host_texels_per_cycle, 1 << 20);
  const std::string md = plan_markdown(half, r);
  EXPECT_NE(md.find("texels a clock, over the key's 1048576"), std::string::npos) << md;
}

TEST(Planner, ABoundNoWidthsMeetNamesTheBestAchievable) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  PlanRequest r = request(d.file("empty.json"));
  r.texel_error = 1e-6;
  const InputError e = test::error_of([&] { make_plan(r); });
  EXPECT_EQ(e.source(), "--texel-error");
  EXPECT_NE(std::string(e.what()).find("the best achievable is"), std::string::npos) << e.what();
}

TEST(Planner, ADepthErrorThatIsNoShareIsRefused) {
  TempDir d;
  write(d.file("empty.json"), R"({"name": "empty", "objects": []})");
  for (const double bad : {-0.1, 1.5, std::nan("")}) {
    PlanRequest r = request(d.file("empty.json"));
    r.depth_error = bad;
    const InputError e = test::error_of([&] { make_plan(r); });
    EXPECT_EQ(e.source(), "--depth-error") << bad;
  }
}

TEST(PriorityLadder, MemoriesUpdateAtTheConfiguredPeriods) {
  host::Scene s;
  host::PriorityConfig pc;
  pc.memories = 3;
  pc.update_frames = 3;
  pc.update_ratio = 4;
  const host::PriorityScheduler sched(s, pc, 64);
  EXPECT_EQ(sched.frames_per_update(0), 3);
  EXPECT_EQ(sched.frames_per_update(1), 12);
  EXPECT_EQ(sched.frames_per_update(2), 48);
  // The slowest memory's period is bounded, named by the key that makes it too long.
  dp::ArpConfig c;
  c.memory.count = 16;
  c.memory.update_ratio = 64;
  const auto issues = dp::validate(c);
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues.front().key, "memory.update_ratio");
  c.memory.update_ratio = 2;
  EXPECT_TRUE(dp::validate(c).empty());
}

// The command: plan.json is a configuration any command reads; a run with another scene warns once.
TEST(PlanCli, ThePlanIsAConfigurationAndKnowsItsScene) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -20]}]})");
  const auto r = run_command(kArpsim + " plan -q --walk gallery --scene " + d.file("far.json") +
                             " --set display.h_active=160 --set display.v_active=120 -o " + d.file("plan.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("| memory.face_size | 161 |"), std::string::npos) << r.output;
  const dp::ArpConfig c = config::load_file(d.file("plan.json"));
  EXPECT_EQ(c.memory.face_size, 161);
  EXPECT_NE(c.plan.scene_hash, 0);
  EXPECT_NE(test::read_text(d.file("plan.md")).find("## Not decided by this plan"), std::string::npos);
  const auto same = run_command(kArpsim + " frame --config " + d.file("plan.json") + " --scene " + d.file("far.json") + " -o " + d.file("a.png"));
  ASSERT_EQ(same.status, 0) << same.output;
  EXPECT_EQ(same.output.find("planned for another scene"), std::string::npos) << same.output;
  const auto other = run_command(kArpsim + " run -q --config " + d.file("plan.json") + " --scene gallery --walk gallery --frames 2 --every 0");
  ASSERT_EQ(other.status, 0) << other.output;
  const std::string warn = d.file("plan.json") + " was planned for another scene";
  const size_t at = other.output.find(warn);
  ASSERT_NE(at, std::string::npos) << other.output;
  EXPECT_EQ(other.output.find(warn, at + 1), std::string::npos) << "warned more than once: " << other.output;
  EXPECT_NE(other.output.find("scene gallery hashes to"), std::string::npos) << other.output;
}

// The plan knows its walk too: the same walk runs quietly; another walk, the
// same walk at another speed, or no walk at all is said once, before the run. So are other eyes (--ipd).
TEST(PlanCli, ThePlanKnowsItsWalk) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -20]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -4]]})");
  write(d.file("other.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -5]]})");
  const std::string small = " --set display.h_active=160 --set display.v_active=120";
  const auto r = run_command(kArpsim + " plan -q --scene " + d.file("far.json") + " --walk " + d.file("walk.json") + small +
                             " -o " + d.file("plan.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(config::load_file(d.file("plan.json")).plan.motion_hash, 0);
  EXPECT_NE(test::read_text(d.file("plan.md")).find("plan.motion_hash"), std::string::npos);
  const std::string run = kArpsim + " run -q --frames 1 --every 0 --config " + d.file("plan.json") + " --scene " + d.file("far.json");
  const std::string warn = d.file("plan.json") + " was planned for ";
  const auto same = run_command(run + " --walk " + d.file("walk.json"));
  ASSERT_EQ(same.status, 0) << same.output;
  EXPECT_EQ(same.output.find(warn), std::string::npos) << same.output;
  for (const std::string& other : std::vector<std::string>{" --walk " + d.file("other.json"), " --walk " + d.file("walk.json") + " --speed 2", ""}) {
    const auto o = run_command(run + other);
    ASSERT_EQ(o.status, 0) << other << "\n" << o.output;
    const size_t at = o.output.find(warn);
    ASSERT_NE(at, std::string::npos) << other << "\n" << o.output;
    EXPECT_EQ(o.output.find(warn, at + 1), std::string::npos) << "warned more than once: " << o.output;
    EXPECT_NE(o.output.find(other.empty() ? "head stays in one place" : "planned for another motion"), std::string::npos) << o.output;
  }
  // And the eyes it planned for (plan.ipd_m): another --ipd is said once, by a run and by a still frame of the scene;
  // a plan made for that --ipd runs quietly with it. Not said without a plan or for one eye; without the scene
  // --ipd is refused (a cube map's image is the same for both eyes).
  EXPECT_DOUBLE_EQ(config::load_file(d.file("plan.json")).plan.ipd_m, dp::kDefaultIpdM);
  const std::string eyes = d.file("plan.json") + " was planned for eyes 64 mm apart (plan.ipd_m 0.064); this run's --ipd is 70 mm";
  const std::string frame = kArpsim + " frame --config " + d.file("plan.json") + " -o " + d.file("f.png") + " --ipd 0.07";
  for (const std::string& wider : {run + " --walk " + d.file("walk.json") + " --ipd 0.07", frame + " --scene " + d.file("far.json")}) {
    const auto o = run_command(wider);
    ASSERT_EQ(o.status, 0) << wider << "\n" << o.output;
    const size_t at = o.output.find(eyes);
    ASSERT_NE(at, std::string::npos) << wider << "\n" << o.output;
    EXPECT_EQ(o.output.find(" was planned for eyes", at + eyes.size()), std::string::npos) << "warned more than once: " << o.output;
  }
  for (const std::string& quiet : {kArpsim + " run -q --frames 1 --every 0 --scene " + d.file("far.json") + " --walk " + d.file("walk.json") + " --ipd 0.07",
                                   run + " --walk " + d.file("walk.json") + " --ipd 0.07 --set display.eyes=1"}) {
    const auto o = run_command(quiet);
    ASSERT_EQ(o.status, 0) << quiet << "\n" << o.output;
    EXPECT_EQ(o.output.find(" was planned for eyes"), std::string::npos) << quiet << "\n" << o.output;
  }
  const auto no_scene = run_command(frame);
  EXPECT_EQ(no_scene.status, 2) << no_scene.output;
  EXPECT_NE(no_scene.output.find("--ipd: only with --scene"), std::string::npos) << no_scene.output;
  EXPECT_EQ(no_scene.output.find(" was planned for eyes"), std::string::npos) << no_scene.output;
  const auto planned = run_command(kArpsim + " plan -q --scene " + d.file("far.json") + " --walk " + d.file("walk.json") + small +
                                   " --ipd 0.07 -o " + d.file("wide.json"));
  ASSERT_EQ(planned.status, 0) << planned.output;
  EXPECT_DOUBLE_EQ(config::load_file(d.file("wide.json")).plan.ipd_m, 0.07);
  const auto same_eyes = run_command(kArpsim + " run -q --frames 1 --every 0 --config " + d.file("wide.json") + " --scene " + d.file("far.json") +
                                     " --walk " + d.file("walk.json") + " --ipd 0.07");
  ASSERT_EQ(same_eyes.status, 0) << same_eyes.output;
  EXPECT_EQ(same_eyes.output.find(" was planned for "), std::string::npos) << same_eyes.output;
}

// And the head's own motion on the walk (--motion, --trace): the same motion runs quietly, and so does the same
// rotation about an axis written longer, or reversed with its rate; no head motion, another rate, or a trace edited after the plan is said once.
// A plan for the walk alone records the walk's hash.
TEST(PlanCli, ThePlanKnowsItsHeadMotion) {
  TempDir d;
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -20]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -4]]})");
  const std::string small = " --set display.h_active=160 --set display.v_active=120 --keep-widths --objects-only";
  const std::string plan = kArpsim + " plan -q --scene " + d.file("far.json") + " --walk " + d.file("walk.json") + small;
  const auto walk_only = run_command(plan + " -o " + d.file("walk-only.json"));
  ASSERT_EQ(walk_only.status, 0) << walk_only.output;
  EXPECT_EQ(config::load_file(d.file("walk-only.json")).plan.motion_hash, host::walk_hash(host::load_walk_file(d.file("walk.json"))));
  const auto turning = run_command(plan + " --motion rotate --rate 30 -o " + d.file("turning.json"));
  ASSERT_EQ(turning.status, 0) << turning.output;
  EXPECT_NE(read_text(d.file("turning.md")).find("the head turning with synthetic rotate at 30 deg/s about 0,1,0"), std::string::npos);
  const int64_t hash = config::load_file(d.file("turning.json")).plan.motion_hash;
  EXPECT_NE(hash, config::load_file(d.file("walk-only.json")).plan.motion_hash);
  const std::string run = kArpsim + " run -q --frames 1 --every 0 --scene " + d.file("far.json") + " --walk " + d.file("walk.json");
  const std::string warn = " was planned for another motion";
  // (0,1e200,0: the axis's length overflows, and normalised it had hashed as no axis at all.)
  for (const std::string& same : {std::string(" --motion rotate --rate 30"), std::string(" --motion rotate --rate 30 --axis 0,2,0"),
                                   std::string(" --motion rotate --rate -30 --axis 0,-1,0"),
                                   std::string(" --motion rotate --rate 30 --axis 0,1e200,0")}) {
    const auto o = run_command(run + " --config " + d.file("turning.json") + same);
    ASSERT_EQ(o.status, 0) << same << "\n" << o.output;
    EXPECT_EQ(o.output.find(warn), std::string::npos) << same << "\n" << o.output;
  }
  for (const std::string& other : {std::string(""), std::string(" --motion rotate --rate 31"), std::string(" --motion shake")}) {
    const auto o = run_command(run + " --config " + d.file("turning.json") + other);
    ASSERT_EQ(o.status, 0) << other << "\n" << o.output;
    const size_t at = o.output.find(warn);
    ASSERT_NE(at, std::string::npos) << other << "\n" << o.output;
    EXPECT_EQ(o.output.find(warn, at + 1), std::string::npos) << "warned more than once: " << o.output;
    EXPECT_NE(o.output.find("hashes to"), std::string::npos) << o.output;
  }
  // A plan for the walk alone, run with a head motion: said too.
  const auto added = run_command(run + " --config " + d.file("walk-only.json") + " --motion rotate --rate 30");
  ASSERT_EQ(added.status, 0) << added.output;
  EXPECT_NE(added.output.find(warn), std::string::npos) << added.output;
  // A trace: its bytes are the motion.
  const auto synth = run_command(kArpsim + " tracker synth --motion shake --seconds 6 -o " + d.file("shake.csv"));
  ASSERT_EQ(synth.status, 0) << synth.output;
  const auto traced = run_command(plan + " --trace " + d.file("shake.csv") + " -o " + d.file("traced.json"));
  ASSERT_EQ(traced.status, 0) << traced.output;
  EXPECT_NE(config::load_file(d.file("traced.json")).plan.motion_hash, hash);
  const auto same_trace = run_command(run + " --config " + d.file("traced.json") + " --trace " + d.file("shake.csv"));
  ASSERT_EQ(same_trace.status, 0) << same_trace.output;
  EXPECT_EQ(same_trace.output.find(warn), std::string::npos) << same_trace.output;
  std::ofstream(d.file("shake.csv"), std::ios::app) << "6.5,1,0,0,0\n";
  const auto edited = run_command(run + " --config " + d.file("traced.json") + " --trace " + d.file("shake.csv"));
  ASSERT_EQ(edited.status, 0) << edited.output;
  EXPECT_NE(edited.output.find(warn), std::string::npos) << edited.output;
  // Both at once: refused, as run refuses them.
  const auto both = run_command(plan + " --trace " + d.file("shake.csv") + " --motion rotate -o " + d.file("both.json"));
  EXPECT_NE(both.status, 0);
  EXPECT_NE(both.output.find("--trace: give either --trace or --motion, not both"), std::string::npos) << both.output;
  EXPECT_FALSE(std::filesystem::exists(d.file("both.json")));
}

// A ball 20 m ahead and a 4 m walk toward it (far.json, walk.json in `d`), planned for a small display
// into plan.json (`extra`: more plan options).
test::CommandResult plan_ball_and_walk(TempDir& d, const std::string& extra = "") {
  write(d.file("far.json"), R"({"name": "far", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -20]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -4]]})");
  return run_command(kArpsim + " plan -q --scene " + d.file("far.json") + " --walk " + d.file("walk.json") +
                     " --set display.h_active=160 --set display.v_active=120" + extra + " -o " + d.file("plan.json"));
}

// `arpsim run` of that plan for 3 frames of its walk (the scene to add).
std::string plan_run_command(TempDir& d) {
  return kArpsim + " run -q --frames 3 --every 0 --error-every 0 --config " + d.file("plan.json") + " --walk " + d.file("walk.json");
}

// That plan run for 3 frames of its scene and walk, as planned (rep[0]) and with `set` (rep[1]), each losing nothing.
void run_plan_both_ways(TempDir& d, const std::string& set, nlohmann::json (&rep)[2]) {
  const std::string run = plan_run_command(d);
  for (int k = 0; k < 2; ++k) {
    const std::string j = d.file("both" + std::to_string(k) + ".json");
    const auto o = run_command(run + " --scene " + d.file("far.json") + (k ? " --set " + set : "") + " --report " + j);
    ASSERT_EQ(o.status, 0) << o.output;
    EXPECT_EQ(o.output.find("were lost"), std::string::npos) << o.output;
    rep[k] = test::load_json(j);
  }
}

// Elaboration follows the plan: the faces it leaves out are not in the memory -- the same frames, the
// footprint smaller by their share (checked against the closed form and the tiles allocated) -- and a
// run that draws on them (another scene) loses those texels and says so once. (Whole faces: the tiles
// have a test of their own.)
TEST(PlanCli, TheFacesAPlanLeavesOutAreNotModelled) {
  TempDir d;
  const auto r = plan_ball_and_walk(d, " --whole-faces");
  ASSERT_EQ(r.status, 0) << r.output;
  const dp::ArpConfig c = config::load_file(d.file("plan.json"));
  ASSERT_EQ(c.memory.faces, (std::array<int, 6>{0, 0, 0, 0, 0, 1}));
  EXPECT_TRUE(std::filesystem::is_regular_file(d.file("plan.tiles.png")));  // the tile picture beside the plan
  const std::string run = plan_run_command(d);
  nlohmann::json rep[2];
  run_plan_both_ways(d, "memory.faces=[1,1,1,1,1,1]", rep);
  EXPECT_EQ(rep[0]["frames"], rep[1]["frames"]);
  const nlohmann::json& fp = rep[0]["footprint"];
  const int64_t S = c.memory.face_size, hw_bits = 2 * c.memory.count * 2 * 1 * S * S * (24 + c.memory.depth_bits), hw = hw_bits / 8;
  EXPECT_EQ(fp["display_memory_faces"], 1);
  EXPECT_EQ(fp["display_memory_bytes_hardware"], hw);
  EXPECT_EQ(rep[1]["footprint"]["display_memory_bytes_hardware"], 6 * hw_bits / 8);
  EXPECT_EQ(fp["texels_lost_on_absent_faces"], 0);
  // The texels the host stored: the ball's, the same with the whole cube, at most one face of each eye for
  // each of the 3 frames' renders and the one before them.
  const int64_t written = fp["texels_written"].get<int64_t>();
  EXPECT_GT(written, 0);
  EXPECT_EQ(rep[1]["footprint"]["texels_written"], written);
  EXPECT_LE(written, 4 * 2 * S * S);
  // What was allocated: the ball's tiles (33 x 33 words of 8 bytes each, at least one an eye) within the peak.
  const int64_t tiles = fp["display_memory_tiles_at_end"].get<int64_t>();
  EXPECT_GE(tiles, 2);
  EXPECT_GE(fp["display_memory_bytes_peak"].get<int64_t>(), tiles * 33 * 33 * 8);
  EXPECT_LT(fp["display_memory_bytes_peak"].get<int64_t>(), hw);
  const auto other = run_command(run + " --scene gallery --report " + d.file("g.json"));
  ASSERT_EQ(other.status, 0) << other.output;
  const std::string lost = "fell on cube faces memory.faces leaves out (+X, -X, +Y, -Y, +Z)";
  const size_t at = other.output.find(lost);
  ASSERT_NE(at, std::string::npos) << other.output;
  EXPECT_EQ(other.output.find(lost, at + 1), std::string::npos) << "said more than once: " << other.output;
  EXPECT_GT(test::load_json(d.file("g.json"))["footprint"]["texels_lost_on_absent_faces"].get<int64_t>(), 0);
}

void write_near_ball(TempDir& d);  // below

// Tiles held, counted from memory.tiles' text independently of dp::TileMap: "*" every tile of a T x T face,
// "-" none, otherwise the set bits of its hex digits.
int64_t tiles_in_text(const std::string& text, int T) {
  int64_t n = 0;
  size_t pos = text.find(':') + 1;  // after the face size
  for (int f = 0; f < 6; ++f) {
    const size_t end = text.find('/', pos);
    const std::string field = text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (field == "*") n += int64_t{T} * T;
    else if (field != "-")
      for (const char ch : field) n += __builtin_popcount(static_cast<unsigned>(std::stoi(std::string(1, ch), nullptr, 16)));
    pos = end + 1;
  }
  return n;
}

// Elaboration follows the plan's tiles (memory.tiles): a run holds only them -- the same frames as holding
// every tile, nothing lost, the hardware figure a tile-sparse memory of those tiles (closed form) -- and a
// run that draws outside them (another scene) loses those texels and says so once.
TEST(PlanCli, TheTilesAPlanLeavesOutAreNotModelled) {
  TempDir d;
  const auto r = plan_ball_and_walk(d);
  ASSERT_EQ(r.status, 0) << r.output;
  const dp::ArpConfig c = config::load_file(d.file("plan.json"));
  ASSERT_EQ(c.memory.tiles.size(), 1u);
  const int T = (c.memory.face_size + 31) / 32;
  const int64_t held = tiles_in_text(c.memory.tiles[0], T);
  EXPECT_GT(held, 0);
  EXPECT_LT(held, T * T);  // on the one face present, part of it
  EXPECT_NE(read_text(d.file("plan.md")).find("| memory.tiles | memory 0: " + std::to_string(held) + " of " + std::to_string(T * T) + " tiles"),
            std::string::npos) << read_text(d.file("plan.md"));
  const std::string run = plan_run_command(d);
  nlohmann::json rep[2];
  run_plan_both_ways(d, "memory.tiles=[]", rep);
  EXPECT_EQ(rep[0]["frames"], rep[1]["frames"]);
  const nlohmann::json& fp = rep[0]["footprint"];
  EXPECT_EQ(fp["texels_lost_off_tiles"], 0);
  EXPECT_EQ(fp["texels_written"], rep[1]["footprint"]["texels_written"]);
  // Two eyes' banks, each both buffers of its tiles' 32 x 32 slots and a tile table of an entry per tile of
  // the face present, wide enough to number them and "absent".
  const int64_t bits = 2 * (2 * held * 1024 * (24 + c.memory.depth_bits) +
                            int64_t{T} * T * static_cast<int64_t>(std::floor(std::log2(static_cast<double>(held))) + 1));
  EXPECT_EQ(fp["display_memory_bytes_hardware"], (bits + 7) / 8);
  const int64_t S = c.memory.face_size;
  EXPECT_EQ(rep[1]["footprint"]["display_memory_bytes_hardware"], 2 * 2 * S * S * (24 + c.memory.depth_bits) / 8);
  write_near_ball(d);
  const auto other = run_command(run + " --scene " + d.file("near.json") + " --report " + d.file("n.json"));
  ASSERT_EQ(other.status, 0) << other.output;
  const std::string lost = "fell on tiles memory.tiles leaves out";
  const size_t at = other.output.find(lost);
  ASSERT_NE(at, std::string::npos) << other.output;
  EXPECT_EQ(other.output.find(lost, at + 1), std::string::npos) << "said more than once: " << other.output;
  EXPECT_GT(test::load_json(d.file("n.json"))["footprint"]["texels_lost_off_tiles"].get<int64_t>(), 0);
  // A face size the list was not made for is refused naming the key, even one with as many tiles a row.
  for (const int size : {512, static_cast<int>(S) + 1}) {
    const auto bad = run_command(run + " --scene " + d.file("far.json") + " --set memory.face_size=" + std::to_string(size));
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.output.find("memory.tiles: memory 0: was listed for faces of " + std::to_string(S) + " texels"), std::string::npos)
        << bad.output;
  }
}

// The plan records the theta_t its memories were sized for (memory.threshold_deg): a run with the plan
// renders by it, --threshold-deg still overrides, and the report's configuration says what ran.
TEST(PlanCli, ARunRendersByThePlansThreshold) {
  TempDir d;
  const auto r = plan_ball_and_walk(d, " --threshold-deg 2.5");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(config::load_file(d.file("plan.json")).memory.threshold_deg, 2.5);
  EXPECT_NE(r.output.find("| memory.threshold_deg | 2.5 |"), std::string::npos) << r.output;
  const std::string run = kArpsim + " run -q --frames 1 --every 0 --error-every 0 --config " + d.file("plan.json") + " --scene " +
                          d.file("far.json") + " --walk " + d.file("walk.json");
  for (const auto& [extra, deg] : std::vector<std::pair<std::string, double>>{{"", 2.5}, {" --threshold-deg 7", 7.0}}) {
    const auto o = run_command(run + extra + " --report " + d.file("r.json"));
    ASSERT_EQ(o.status, 0) << o.output;
    const nlohmann::json rep = test::load_json(d.file("r.json"));
    EXPECT_DOUBLE_EQ(rep["host"]["threshold_deg"].get<double>(), deg) << extra;
    EXPECT_DOUBLE_EQ(rep["config"]["memory"]["threshold_deg"].get<double>(), deg) << extra;
  }
  // Planned again from the plan, with no --threshold-deg: the same theta_t.
  const auto again = run_command(kArpsim + " plan -q --config " + d.file("plan.json") + " --scene " + d.file("far.json") + " --walk " +
                                 d.file("walk.json") + " -o " + d.file("plan2.json"));
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(config::load_file(d.file("plan2.json")).memory.threshold_deg, 2.5);
}

// A ball of 0.5 m two metres ahead of the walks below (near.json).
void write_near_ball(TempDir& d) {
  write(d.file("near.json"), R"({"name": "near", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -2]}]})");
}

// The ball and a walk of a metre toward it at 1 m/s (walk.json), planned with the starting widths kept.
PlanRequest near_ball_and_walk_toward(TempDir& d) {
  write_near_ball(d);
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  PlanRequest r = request(d.file("near.json"), d.file("walk.json"));
  r.size_widths = false;
  return r;
}

// The engine's fill counts. A ball near the eye, with the engine's triangles and set-up made free: its fill
// is all the engine does, and the plan's busy share is what a run with the plan reports of its modelled
// engine (host.memories[].engine_busy_s over the simulated seconds: the host simulation's own account of
// the texels its renders filled), within what the eyes' 32 mm either side of the walk's point change.
TEST(PlanCli, ThePlansEngineBusyIsWhatARunsEngineIs) {
  TempDir d;
  write_near_ball(d);
  // Standing still, and walking a metre toward the ball (its fill grows about fourfold: the plan renders 16
  // points of the walk and interpolates between them). Until the planner sampled only within the motion,
  // its last point was past a looping walk's end, back at the start, and the walk was 7 % under.
  write(d.file("still.json"), R"({"speed": 0, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  write(d.file("toward.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  for (const std::string walk : {"still", "toward"}) {
    PlanRequest r = request(d.file("near.json"), d.file(walk + ".json"));
    r.size_widths = false;
    r.base.host.object_setup_s = 0;
    r.base.host.triangles_per_s = 1e15;
    r.base.host.texels_per_s = 1e7;
    const Plan p = make_plan(r);
    const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
    ASSERT_GT(p.planned.texels_per_s, 0) << walk;
    EXPECT_NEAR(p.planned.engine_busy, p.planned.texels_per_s / 1e7, 1e-6 * p.planned.engine_busy) << walk;  // the fill is all of it
    write(d.file("plan.json"), plan_config_text(p));
    // Still: four updates of its one memory. Walking: the whole walk.
    const int frames = walk == "still" ? 4 * p.config.memory.update_frames : static_cast<int>(std::lround(p.motion_s * hz));
    const auto o = run_command(kArpsim + " run -q --every 0 --error-every 0 --frames " + std::to_string(frames) + " --config " +
                               d.file("plan.json") + " --scene " + d.file("near.json") + " --walk " + d.file(walk + ".json") +
                               " --report " + d.file("r.json"));
    ASSERT_EQ(o.status, 0) << o.output;
    const nlohmann::json rep = test::load_json(d.file("r.json"));
    double busy_s = 0;
    int64_t updates = 0;
    for (const auto& m : rep["host"]["memories"]) {
      busy_s += m["engine_busy_s"].get<double>();
      updates += m["updates"].get<int64_t>();
    }
    int64_t due = 0;  // each memory's updates in `frames` frames, from frame 0
    for (int m = 0; m < p.config.memory.count; ++m) {
      const int64_t period = dp::update_period_frames(p.config.memory.update_frames, p.config.memory.update_ratio, m);
      due += (frames + period - 1) / period;
    }
    EXPECT_EQ(updates, walk == "still" ? 4 : due) << walk;
    EXPECT_NEAR(busy_s / (frames / hz), p.planned.engine_busy, 0.02 * p.planned.engine_busy) << walk;
  }
}

// --fill-points: the fill measured at more points of the motion follows it more closely. Walking a metre toward the
// ball its fill grows about fourfold along a curve (as the inverse square of the distance), which a line between
// two points (the walk's ends) overstates in between; 64 points come within 1 % of a run's engine.
TEST(PlanCli, MoreFillPointsFollowTheFill) {
  TempDir d;
  write_near_ball(d);
  write(d.file("toward.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  double busy[2] = {0, 0};
  int i = 0;
  for (const int points : {2, 64}) {
    PlanRequest r = request(d.file("near.json"), d.file("toward.json"));
    r.size_widths = false;
    r.base.host.object_setup_s = 0;
    r.base.host.triangles_per_s = 1e15;
    r.base.host.texels_per_s = 1e7;
    r.fill_points = points;
    const Plan p = make_plan(r);
    EXPECT_EQ(p.fill_points, points);
    busy[i++] = p.planned.engine_busy;
    if (points == 2) continue;
    write(d.file("plan.json"), plan_config_text(p));
    const int frames = static_cast<int>(std::lround(p.motion_s * dp::VideoTiming(r.base.timing).refresh_hz()));
    const auto o = run_command(kArpsim + " run -q --every 0 --error-every 0 --frames " + std::to_string(frames) + " --config " +
                               d.file("plan.json") + " --scene " + d.file("near.json") + " --walk " + d.file("toward.json") +
                               " --report " + d.file("r.json"));
    ASSERT_EQ(o.status, 0) << o.output;
    double run_busy = 0;
    const nlohmann::json rep = test::load_json(d.file("r.json"));
    for (const auto& m : rep["host"]["memories"]) run_busy += m["engine_busy_s"].get<double>();
    run_busy /= frames / dp::VideoTiming(r.base.timing).refresh_hz();
    EXPECT_NEAR(busy[1], run_busy, 0.01 * run_busy);
    EXPECT_GT(busy[0] - run_busy, 3 * std::abs(busy[1] - run_busy)) << busy[0] << " " << busy[1] << " " << run_busy;
  }
}

// The engine a plan says it needs is what a run's engine needs: the host simulation (its own queue of renders,
// from the triangles its renderer sent) skips no update with an engine 2 % faster than the plan's least, and skips
// some with one 3 % slower. A ball two metres ahead of a walk toward it, inside the -Z face of both eyes all along,
// so the plan's count of the triangles sent (its bound's faces) is the renderer's; the fill made negligible.
// The write port the plan sizes stores the least engine's fill at the host clock.
TEST(PlanCli, ARunSkipsNoUpdateWithTheEngineThePlanNeedsAndSomeWithLess) {
  TempDir d;
  PlanRequest r = near_ball_and_walk_toward(d);
  r.base.host.object_setup_s = 0;
  r.base.host.texels_per_s = 1e15;
  const Plan p = make_plan(r);
  const double need = p.planned_need.scale;
  ASSERT_GT(need, 0);
  EXPECT_EQ(p.config.timed.host_texels_per_cycle,
            static_cast<int>(std::ceil(need * 1e15 / static_cast<double>(p.config.timed.host_clock_hz))));
  write(d.file("plan.json"), plan_config_text(p));
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const int frames = static_cast<int>(std::lround(p.motion_s * hz));
  for (const double factor : {1.02, 0.97}) {
    const auto o = run_command(kArpsim + " run -q --every 0 --error-every 0 --frames " + std::to_string(frames) + " --config " +
                               d.file("plan.json") + " --scene " + d.file("near.json") + " --walk " + d.file("walk.json") +
                               " --engine-setup 0 --engine-fill 1e15 --engine-triangles " +
                               printf_text("%.17g", factor * need * r.base.host.triangles_per_s) + " --report " + d.file("r.json"));
    ASSERT_EQ(o.status, 0) << o.output;
    const nlohmann::json rep = test::load_json(d.file("r.json"));
    int64_t skipped = 0, updates = 0;
    for (const auto& m : rep["host"]["memories"]) {
      skipped += m["skipped_overload"].get<int64_t>();
      updates += m["updates"].get<int64_t>();
    }
    ASSERT_GT(updates, 10) << factor;
    if (factor > 1) EXPECT_EQ(skipped, 0) << "engine " << factor << " x the plan's least";
    else EXPECT_GT(skipped, 0) << "engine " << factor << " x the plan's least";
    // Planned with that engine, the same ladder, and the plan counts the updates the run skips: the ball moves from
    // the slower memory to the faster as the walk nears it, and the plan moves it as a run does (only in a frame
    // both memories render, the two swapping together).
    PlanRequest with = r;
    with.base.host.triangles_per_s = factor * need * r.base.host.triangles_per_s;
    const Plan q = make_plan(with);
    ASSERT_EQ(std::make_tuple(q.planned.count, q.planned.update_frames, q.planned.update_ratio),
              std::make_tuple(p.planned.count, p.planned.update_frames, p.planned.update_ratio)) << factor;
    EXPECT_EQ(q.planned_need.skipped, skipped) << factor;
  }
}

// The starting configuration of the engine-replay tests against runs: 60 Hz, two memories every 1 and 4 frames,
// theta_t 5 degrees, no set-up per object, the engine's fill and triangle rates as given.
dp::ArpConfig two_memories_every_1_and_4(const std::string& texels_per_s, const std::string& triangles_per_s) {
  return config::apply_overrides(small_display_60hz(), {"memory.count=2", "memory.update_ratio=4", "memory.threshold_deg=5",
                                                        "host.object_setup_s=0", "host.texels_per_s=" + texels_per_s,
                                                        "host.triangles_per_s=" + triangles_per_s});
}

// The display frames the plan's engine replay covers (the walk's motion at the configuration's rate).
int replay_frames(const Plan& p, const dp::ArpConfig& c) {
  return static_cast<int>(std::floor(p.motion_s * dp::VideoTiming(c.timing).refresh_hz())) + 1;
}

// `arpsim run` of configuration `c` over `frames` frames of a walk through a scene: its report, two memories checked
// (null where the run failed: a failure, said).
nlohmann::json run_two_memories(const TempDir& d, const dp::ArpConfig& c, const std::string& scene, const std::string& walk, int frames) {
  std::ofstream(d.file("base.json")) << config::to_json(c).dump(2);
  std::filesystem::remove(d.file("r.json"));  // (not the report of a run before)
  const auto o = run_command(kArpsim + " run -q --every 0 --error-every 0 --frames " + std::to_string(frames) + " --config " +
                             d.file("base.json") + " --scene " + scene + " --walk " + walk + " --report " + d.file("r.json"));
  EXPECT_EQ(o.status, 0) << o.output;
  if (o.status != 0) return nlohmann::json();
  const nlohmann::json rep = test::load_json(d.file("r.json"));
  const bool two = rep.contains("host") && rep["host"].contains("memories") && rep["host"]["memories"].size() == 2u;
  EXPECT_TRUE(two) << rep.dump();
  return two ? rep : nlohmann::json();
}

// Memories exchanging an object swap together, at the last of them to finish, in the plan's replay as in a run: a
// ball walked past moves from memory 1 (every 4th frame) to memory 0 (every frame) in a frame both render, while
// memory 1 holds a far sphere whose render takes about 2.5 frames (20 000 triangles for each eye at 4.8e5 a second).
// Memory 0's image of that frame then waits for memory 1's, and its next update is skipped too: one skip more than
// the engine's queue alone gives (seen failing with the joint swap dropped from the replay: 23 against the run's 24).
// The starting configuration's ladder, replayed (Plan::base_need), against a run of it over the whole walk at 60 Hz.
TEST(PlanCli, MemoriesExchangingAnObjectSwapTogetherAsInARun) {
  TempDir d;
  write(d.file("pass.json"), R"({"name": "pass", "objects": [{"name": "ball", "sphere": 0.3, "segments": 8, "position": [0.5, 1.6, -1.5]},
    {"name": "far", "sphere": 2, "segments": 100, "position": [0, 1.6, -40]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -1.5]]})");
  PlanRequest r = request(d.file("pass.json"), d.file("walk.json"));
  r.base = two_memories_every_1_and_4("1e15", "4.8e5");
  r.size_widths = false;
  const Plan p = make_plan(r);
  ASSERT_EQ(std::make_tuple(p.base_ladder.count, p.base_ladder.update_frames, p.base_ladder.update_ratio), std::make_tuple(2, 1, 4));
  const auto run = [&](int n) { return run_two_memories(d, r.base, d.file("pass.json"), d.file("walk.json"), n); };
  // The ball starts in memory 1 with the far sphere and ends in memory 0 (objects_now: both eyes' memories hold the same).
  const nlohmann::json first = run(1);
  ASSERT_FALSE(first.is_null());
  EXPECT_EQ(first["host"]["memories"][0]["objects_now"], 0);
  EXPECT_EQ(first["host"]["memories"][1]["objects_now"], 2);
  const nlohmann::json rep = run(replay_frames(p, r.base));
  ASSERT_FALSE(rep.is_null());
  EXPECT_EQ(rep["host"]["memories"][0]["objects_now"], 1);
  EXPECT_EQ(rep["host"]["memories"][1]["objects_now"], 1);
  const int64_t skipped = rep["host"]["memories"][0]["skipped_overload"].get<int64_t>();
  EXPECT_EQ(rep["host"]["memories"][1]["skipped_overload"], 0);  // memory 1's own render fits in its period
  EXPECT_GT(skipped, 0);
  EXPECT_EQ(p.base_need.skipped, skipped);
}

// A memory's render draws only its own objects: a far sphere in memory 1 fills all it covers there, though from the
// walk it is hidden behind a near wall in memory 0 (drawn first, so the sphere fails the depth test in a render of the
// whole scene). The engine is limited by its fill. The least engine of the starting ladder (2 memories every 1 and 4
// frames), with each memory's objects rendered on their own, carries a run with 2 % to spare and not with 3 % less;
// with the whole scene's fill (the sphere's 0) it was 2.88 times the configured engine against 3.66, and a run at
// 1.02 times it skipped 11 renders (seen failing so).
TEST(PlanCli, TheLeastEngineCountsWhatAMemoryFillsOnItsOwn) {
  TempDir d;
  write(d.file("hidden.json"), R"({"name": "hidden", "objects": [{"name": "wall", "box": [8, 6, 0.1], "position": [0, 1.6, -3]},
    {"name": "far", "sphere": 30, "segments": 24, "position": [0, 1.6, -45]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  PlanRequest r = request(d.file("hidden.json"), d.file("walk.json"));
  r.base = two_memories_every_1_and_4("2e7", "1e15");
  r.size_widths = false;
  r.fill_points = 64;
  const Plan p = make_plan(r);
  ASSERT_EQ(std::make_tuple(p.base_ladder.count, p.base_ladder.update_frames, p.base_ladder.update_ratio), std::make_tuple(2, 1, 4));
  const double need = p.base_need.scale;
  ASSERT_GT(need, 0);
  for (const double factor : {1.02, 0.97}) {
    dp::ArpConfig c = r.base;
    c.host.texels_per_s = factor * need * r.base.host.texels_per_s;
    const nlohmann::json rep = run_two_memories(d, c, d.file("hidden.json"), d.file("walk.json"), replay_frames(p, r.base));
    ASSERT_FALSE(rep.is_null()) << factor;
    EXPECT_EQ(rep["host"]["memories"][0]["objects_now"], 1) << "the wall in memory 0";
    EXPECT_EQ(rep["host"]["memories"][1]["objects_now"], 1) << "the sphere in memory 1";
    int64_t skipped = 0;
    for (const auto& m : rep["host"]["memories"]) skipped += m["skipped_overload"].get<int64_t>();
    if (factor > 1) EXPECT_EQ(skipped, 0) << "engine " << factor << " x the plan's least";
    else EXPECT_GT(skipped, 0) << "engine " << factor << " x the plan's least";
  }
}

// The FIFOs are the smallest the configuration allows, and a cycle-level run of the plan, the host
// rendering into its memories, shows why: nothing stalls, each inter-stage FIFO holds one token, the
// scan-out FIFO the issue slack and one, and no write is blocked.
TEST(PlanCli, TheFifosAreTheSmallestAndNothingStalls) {
  TempDir d;
  PlanRequest r = near_ball_and_walk_toward(d);
  r.base.timed.issue_slack_cycles = 5;
  r.base.timed.fifo_depth = 64;
  const Plan p = make_plan(r);
  EXPECT_EQ(p.config.timed.fifo_depth, 7);
  write(d.file("plan.json"), plan_config_text(p));
  const auto o = run_command(kArpsim + " run -q --fidelity cycle --every 0 --error-every 0 --frames 3 --config " +
                             d.file("plan.json") + " --scene " + d.file("near.json") + " --walk " + d.file("walk.json") +
                             " --report " + d.file("r.json"));
  ASSERT_EQ(o.status, 0) << o.output;
  const nlohmann::json rep = test::load_json(d.file("r.json"));
  EXPECT_EQ(rep["underflows"], 0);
  ASSERT_FALSE(rep["fifos"].empty());
  for (const auto& f : rep["fifos"]) {
    EXPECT_EQ(f["depth"], 7);
    EXPECT_EQ(f["blocked_writes"], 0) << f["fifo"];
    EXPECT_EQ(f["max_occupancy"], f["fifo"] == "pixel_colors" ? 6 : 1) << f["fifo"];
  }
  int64_t updates = 0;
  for (const auto& m : rep["host"]["memories"]) updates += m["updates"].get<int64_t>();
  EXPECT_GT(updates, 0);  // the host did render while the pipeline ran
}

// One memory composes nothing: the plan keeps the narrowest depth code (1 bit: a written flag, its other
// value the reserved "empty" code), and a run of it shows the same frames as with the 16-bit code, in a
// display memory of (24 + 1) / (24 + 16) the size (eyes x 2 buffers x faces x S^2 x texel bits).
TEST(PlanCli, OneMemoryKeepsTheNarrowestDepthCodeAndShowsTheSameFrames) {
  TempDir d;
  const auto r = plan_ball_and_walk(d, " --whole-faces");
  ASSERT_EQ(r.status, 0) << r.output;
  const dp::ArpConfig c = config::load_file(d.file("plan.json"));
  ASSERT_EQ(c.memory.count, 1);
  EXPECT_EQ(c.memory.depth_bits, 1);
  EXPECT_NE(read_text(d.file("plan.md")).find("| memory.depth_bits | 1 | one memory"), std::string::npos);
  nlohmann::json rep[2];
  for (int wide = 0; wide < 2; ++wide) {
    const std::string j = d.file("r" + std::to_string(wide) + ".json");
    const auto o = run_command(kArpsim + " run -q --frames 3 --every 0 --error-every 0 --config " + d.file("plan.json") + " --scene " +
                               d.file("far.json") + " --walk " + d.file("walk.json") + (wide ? " --set memory.depth_bits=16" : "") +
                               " --report " + j);
    ASSERT_EQ(o.status, 0) << o.output;
    rep[wide] = test::load_json(j);
  }
  EXPECT_EQ(rep[0]["frames"], rep[1]["frames"]);
  const int64_t S = c.memory.face_size, faces = c.memory.faces_present();
  EXPECT_EQ(rep[0]["footprint"]["display_memory_bytes_hardware"], 2 * 2 * faces * S * S * 25 / 8);
  EXPECT_EQ(rep[1]["footprint"]["display_memory_bytes_hardware"], 2 * 2 * faces * S * S * 40 / 8);
}

// Several memories whose nearer surfaces are always in the faster memory: a ball walked toward before a
// wall 300 m away. Every texel the two share is won by the ball, in memory 0, at any width -- ties
// included -- so the plan takes a 1-bit code, and a run of it shows the same frames as with 16 bits.
TEST(PlanCli, ANearBallBeforeAFarWallComposesRightWithAOneBitDepthCode) {
  TempDir d;
  write(d.file("wall.json"), R"({"name": "wall", "objects": [{"name": "ball", "sphere": 0.5, "position": [0, 1.6, -3]},
    {"name": "wall", "quad": [400, 400, 0], "position": [0, 1.6, -300]}]})");
  write(d.file("walk.json"), R"({"speed": 1.0, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  const auto r = run_command(kArpsim + " plan -q --scene " + d.file("wall.json") + " --walk " + d.file("walk.json") +
                             " --threshold-deg 1 --objects-only --set display.h_active=160 --set display.v_active=120 -o " + d.file("plan.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  const dp::ArpConfig c = config::load_file(d.file("plan.json"));
  ASSERT_GT(c.memory.count, 1);
  EXPECT_EQ(c.memory.depth_bits, 1);
  const std::string md = read_text(d.file("plan.md"));
  EXPECT_NE(md.find("every nearer surface is in a faster memory"), std::string::npos) << md;
  const auto at = md.find(" texels where two or more memories hold a surface");  // the ball is seen against the wall
  ASSERT_NE(at, std::string::npos) << md;
  EXPECT_GT(std::stoll(md.substr(md.rfind(' ', at - 1) + 1)), 1000) << md;
  nlohmann::json rep[2];
  for (int wide = 0; wide < 2; ++wide) {
    const std::string j = d.file("r" + std::to_string(wide) + ".json");
    const auto o = run_command(kArpsim + " run -q --frames 4 --every 0 --error-every 0 --config " + d.file("plan.json") +
                               " --scene " + d.file("wall.json") + " --walk " + d.file("walk.json") +
                               (wide ? " --set memory.depth_bits=16" : "") + " --report " + j);
    ASSERT_EQ(o.status, 0) << o.output;
    rep[wide] = test::load_json(j);
  }
  EXPECT_EQ(rep[0]["frames"], rep[1]["frames"]);
}

// host::object_face_rect against the renderer: every texel an object covers on a face, drawn from the eye or
// from anywhere within the margin of it, lies in the rectangle; for a box square to the faces and wholly in
// front of one, the rectangle is the box's outline to within the texel it is grown by and a rounding.
TEST(FaceFootprint, AnObjectsTexelsLieInItsRectangleFromAnyEyeWithinTheMargin) {
  constexpr int S = 64;
  const double near_m = host::DepthCode{}.near_m;
  struct Case {
    glm::dvec3 size, position;
    double yaw_deg;
    bool square_in_front;  // an unrotated box wholly in front of face -Z, within it
  };
  const std::vector<Case> cases{{{1.0, 2.0, 0.5}, {0.3, -0.2, -3.0}, 0, true},
                                {{1.0, 2.0, 0.5}, {2.0, 1.0, -2.0}, 30, false},     // on a corner: three faces
                                {{0.2, 1.0, 6.0}, {1.5, 0.0, 0.0}, 0, false},       // beside the eye, through the +-Z near planes
                                {{0.4, 0.4, 0.4}, {0.0, 0.0, -0.3}, 45, false}};    // near
  host::CubeFaceRenderer renderer;
  int outside_without_margin = 0;
  for (const Case& c : cases) {
    host::Scene scene;
    host::SceneObject& o = host::add_object(scene, "box", std::make_shared<host::Mesh>(host::make_box(c.size)), c.position, {});
    o.rotation_deg = {c.yaw_deg, 0, 0};
    const auto box = host::mesh_box(*o.mesh);
    const double margin = 0.03;
    std::vector<glm::dvec3> eyes{glm::dvec3(0.0)};
    for (int k = 0; k < 8; ++k) eyes.push_back({k & 1 ? margin : -margin, k & 2 ? margin : -margin, k & 4 ? margin : -margin});
    int drawn = 0;
    for (size_t e = 0; e < eyes.size(); ++e) {
      std::vector<host::FaceImage> faces;
      renderer.render_faces(scene, {}, 0.0, eyes[e], S, faces);
      for (int f = 0; f < 6; ++f) {
        const host::TexelRect r = host::object_face_rect(o, box, 0.0, glm::dvec3(0.0), e ? margin : 0.0, f, S, near_m);
        const host::TexelRect tight = host::object_face_rect(o, box, 0.0, glm::dvec3(0.0), 0.0, f, S, near_m);
        host::TexelRect seen{S, S, -1, -1};
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x) {
            const auto& ids = faces[static_cast<size_t>(f)].object;  // (empty: nothing reached the face)
            if (ids.empty() || ids[static_cast<size_t>(y * S + x)] == 0) continue;
            ++drawn;
            seen = {std::min(seen.x0, x), std::min(seen.y0, y), std::max(seen.x1, x), std::max(seen.y1, y)};
            ASSERT_TRUE(x >= r.x0 && x <= r.x1 && y >= r.y0 && y <= r.y1)
                << "case at " << c.position.x << "," << c.position.z << " eye " << e << " face " << f << " texel " << x << "," << y;
            if (x < tight.x0 || x > tight.x1 || y < tight.y0 || y > tight.y1) ++outside_without_margin;
          }
        if (c.square_in_front && e == 0) {
          if (f != 5) {
            EXPECT_TRUE(r.empty() && seen.empty()) << f;
            continue;
          }
          EXPECT_GE(seen.x0 - r.x0, 1);
          EXPECT_LE(seen.x0 - r.x0, 2);
          EXPECT_GE(r.x1 - seen.x1, 1);
          EXPECT_LE(r.x1 - seen.x1, 2);
          EXPECT_GE(seen.y0 - r.y0, 1);
          EXPECT_LE(seen.y0 - r.y0, 2);
          EXPECT_GE(r.y1 - seen.y1, 1);
          EXPECT_LE(r.y1 - seen.y1, 2);
        }
      }
    }
    EXPECT_GT(drawn, 0);
  }
  EXPECT_GT(outside_without_margin, 0);  // the eyes' offsets draw where the margin-less rectangle does not reach
}

// The plan's tiles drawn on bound a run's: a row of balls near and far beside a walk, planned into several
// memories, run over the whole walk with the plan -- every tile any bank's objects were drawn on is within
// the plan's bound for that memory, and the bound is a small part of the faces.
TEST(Planner, TheTilesARunDrawsOnAreWithinThePlansBound) {
  TempDir d;
  PlanRequest r = ball_row(d, 5, [](int i) { return -1.5 * (i + 1); }, 3, 0.5);
  r.base = small_display_60hz();
  r.tile_pool = false;  // --fixed-tiles: the run holds the plan's tiles
  const Plan p = make_plan(r);
  ASSERT_GT(p.config.memory.count, 1);
  RunSpec spec;
  spec.config = p.config;
  spec.memories.scene = d.file("row.json");
  spec.host.walk = d.file("walk.json");
  spec.frames = static_cast<int64_t>(std::ceil(3.0 * dp::VideoTiming(p.config.timing).refresh_hz()));
  spec.out.out_dir = d.file("run");
  spec.out.every = 0;
  spec.out.error_every = 0;
  Session session(spec);
  session.run();
  const dp::DisplayMemorySet& mem = session.memories();
  const int tpr = p.tiles.tiles_per_row;
  ASSERT_EQ(mem.bank(0, 0).tiles_per_row(), tpr);
  int64_t drawn = 0, bound = 0;
  std::vector<int64_t> drawn_in(static_cast<size_t>(p.config.memory.count), 0);
  for (int m = 0; m < p.config.memory.count; ++m) {
    bound += p.tiles.per_memory[static_cast<size_t>(m)];
    for (int e = 0; e < mem.eyes(); ++e)
      for (int f = 0; f < 6; ++f)
        for (int ty = 0; ty < tpr; ++ty)
          for (int tx = 0; tx < tpr; ++tx)
            if (mem.bank(e, m).tile_ever_written(f, tx, ty)) {
              ++drawn;
              ++drawn_in[static_cast<size_t>(m)];
              EXPECT_TRUE(p.tiles.reachable(m, f, tx, ty)) << "memory " << m << " eye " << e << " face " << f << " tile " << tx << "," << ty;
            }
  }
  int used = 0;
  for (const int64_t n : drawn_in) used += n > 0 ? 1 : 0;
  EXPECT_GT(used, 1);  // objects were drawn in several memories
  EXPECT_GT(drawn, 0);
  EXPECT_LT(bound, p.config.memory.count * p.config.memory.faces_present() * tpr * tpr / 4);
  EXPECT_LE(bound * mem.eyes(), 4 * drawn);  // and not loose: within 4x what the run drew on
  EXPECT_LT(p.memory_bytes_tiled, p.memory_bytes_whole / 2);
  // The run held only the plan's tiles (memory.tiles) and lost no texel for it.
  ASSERT_EQ(p.config.memory.tiles.size(), static_cast<size_t>(p.config.memory.count));
  EXPECT_EQ(mem.writes_lost_off_tiles(), 0);
  EXPECT_EQ(p.memory_bytes_planned, p.memory_bytes_tiled);
  // The plan's tile-sparse figure in closed form: for each eye's bank of each memory, both buffers of its
  // tiles' 32 x 32 slots and a table of an entry per tile of each face present, wide enough for 0 .. tiles.
  int64_t bits = 0;
  for (int e = 0; e < 2; ++e)
    for (const int64_t t : p.tiles.per_memory)
      bits += 2 * t * 1024 * (24 + p.config.memory.depth_bits) +
              int64_t{p.config.memory.faces_present()} * tpr * tpr * static_cast<int64_t>(std::ceil(std::log2(static_cast<double>(t) + 1)));
  EXPECT_EQ(p.memory_bytes_tiled, (bits + 7) / 8);
  // The tile pool the plan costs: no fewer slots than the run's banks had in use at once (both buffers).
  for (int m = 0; m < p.config.memory.count; ++m) {
    EXPECT_GE(p.tiles.pooled[static_cast<size_t>(m)], mem.tiles_most_at_once(m)) << m;
    EXPECT_GT(mem.tiles_most_at_once(m), 0) << m;
  }
  // The run's own pool figure: every bank's slots in use at once in closed form.
  int64_t pooled_bits = 0;
  for (int e = 0; e < mem.eyes(); ++e)
    for (int m = 0; m < p.config.memory.count; ++m) {
      const int64_t n = mem.bank(e, m).tiles_most_at_once();
      pooled_bits += n * 1024 * (24 + p.config.memory.depth_bits) +
                     2 * int64_t{p.config.memory.faces_present()} * tpr * tpr * static_cast<int64_t>(std::ceil(std::log2(static_cast<double>(n) + 1)));
    }
  EXPECT_EQ(display_memory_bytes_pooled(p.config, mem), (pooled_bits + 7) / 8);
  // The picture: a row of six faces for each memory, a reachable tile light and another dark.
  const host::RgbImage img = plan_tiles_image(p);
  const int face_px = tpr * kTilePixels;
  ASSERT_EQ(img.width, kTilePixels + 6 * (face_px + kTilePixels));
  ASSERT_EQ(img.height, kTilePixels + p.config.memory.count * (face_px + kTilePixels));
  int light = 0, dark = 0, left_out = 0;
  for (int m = 0; m < p.config.memory.count; ++m)
    for (int f = 0; f < 6; ++f)
      for (int ty = 0; ty < tpr; ++ty)
        for (int tx = 0; tx < tpr; ++tx) {
          const uint8_t* px = img.px(kTilePixels + f * (face_px + kTilePixels) + tx * kTilePixels + 1,
                                     kTilePixels + m * (face_px + kTilePixels) + ty * kTilePixels + 2);
          const bool face_kept = p.config.memory.faces[static_cast<size_t>(f)] != 0;
          if (!face_kept) {
            EXPECT_EQ(px[0], 90);
            EXPECT_EQ(px[1], 0);
            ++left_out;
          } else if (p.tiles.reachable(m, f, tx, ty)) {
            EXPECT_GT(px[0], 200);
            ++light;
          } else {
            EXPECT_LT(px[0], 60);
            ++dark;
          }
        }
  EXPECT_EQ(light, bound);
  EXPECT_GT(dark, 0);
  EXPECT_GT(left_out, 0);  // (the balls are ahead and to the right: faces are left out)
}

// A plan takes a tile pool (memory.tile_pool) for a memory where that takes less than its tiles or whole faces:
// the row of balls near and far beside a walk. Its figure is the closed form (per eye and memory, the pool's
// slots once and a tile table per buffer of an entry per tile of each face present, wide enough for 0 .. slots;
// whole faces or fixed tiles for the others), less than the fixed tiles'. Run over the whole walk, the pooled
// memories lose no texel and hold, texel for texel, what the fixed-tile plan's run holds; each bank used no more
// slots than its pool. Every memory with one slot loses texels in memory 0 (it has no faster memory to hand objects
// to), counts them and warns once, at both levels alike.
// (Seen failing with the pool's slots counted once per buffer, and with the run given no pool.)
TEST(Planner, APlannedTilePoolHoldsWhatARunDrawsAndChangesNoTexel) {
  TempDir d;
  PlanRequest r = ball_row(d, 5, [](int i) { return -1.5 * (i + 1); }, 3, 0.5);
  r.tile_pool = false;
  const Plan fixed = make_plan(r);
  r.tile_pool = true;
  const Plan p = make_plan(r);
  const int M = p.config.memory.count;
  ASSERT_EQ(M, fixed.config.memory.count);
  ASSERT_EQ(p.config.memory.tile_pool.size(), static_cast<size_t>(M));
  const int64_t S = p.config.memory.face_size, tpr = (S + 31) / 32, F = p.config.memory.faces_present(),
                bits = 24 + p.config.memory.depth_bits;
  std::vector<dp::TileMap> maps;
  std::string why;
  ASSERT_TRUE(dp::tile_maps(p.config.memory, maps, why)) << why;
  int64_t total = 0;
  int pooled = 0;
  for (int m = 0; m < M; ++m) {
    const int64_t slots = p.config.memory.tile_pool[static_cast<size_t>(m)];
    if (slots > 0) {
      ++pooled;
      EXPECT_EQ(slots, p.tiles.pooled[static_cast<size_t>(m)]) << m;
      EXPECT_TRUE(maps[static_cast<size_t>(m)].every_tile(dp::MemoryFormat(p.config.memory).present)) << m;  // the pool's tables address every tile
      total += 2 * (slots * 1024 * bits + 2 * F * tpr * tpr * static_cast<int64_t>(std::floor(std::log2(static_cast<double>(slots))) + 1));
    } else if (const int64_t held = tiles_held(p.config, m); held >= 0) {
      total += 2 * (2 * held * 1024 * bits + F * tpr * tpr * static_cast<int64_t>(std::floor(std::log2(static_cast<double>(held))) + 1));
    } else {
      total += 2 * 2 * F * S * S * bits;
    }
  }
  ASSERT_GT(pooled, 0);
  EXPECT_EQ(p.memory_bytes_planned, (total + 7) / 8);
  EXPECT_EQ(p.memory_bytes_planned, p.memory_bytes_pooled);
  EXPECT_LT(p.memory_bytes_planned, fixed.memory_bytes_planned);
  EXPECT_EQ(p.memory_bytes_fixed_tiles, fixed.memory_bytes_planned);
  auto run = [&](const dp::ArpConfig& c, const std::string& dir) {
    RunSpec spec;
    spec.config = c;
    spec.memories.scene = d.file("row.json");
    spec.host.walk = d.file("walk.json");
    spec.frames = static_cast<int64_t>(std::ceil(3.0 * dp::VideoTiming(c.timing).refresh_hz()));
    spec.out.out_dir = d.file(dir);
    spec.out.every = 0;
    spec.out.error_every = 0;
    auto session = std::make_unique<Session>(spec);
    session->run();
    return session;
  };
  const auto with_pool = run(p.config, "pool"), with_tiles = run(fixed.config, "tiles");
  const dp::DisplayMemorySet &a = with_pool->memories(), &b = with_tiles->memories();
  EXPECT_EQ(a.writes_lost_pool_full(), 0);
  EXPECT_EQ(a.writes_lost_off_tiles(), 0);
  EXPECT_EQ(b.writes_lost_off_tiles(), 0);
  EXPECT_EQ(a.texels_written(), b.texels_written());
  for (int m = 0; m < M; ++m) {
    const int64_t slots = p.config.memory.tile_pool[static_cast<size_t>(m)];
    if (slots > 0) {
      EXPECT_LE(a.tiles_most_at_once(m), slots) << m;
      EXPECT_EQ(a.bank(0, m).pool_slots(), slots);
    }
    for (int e = 0; e < a.eyes(); ++e)
      for (int f = 0; f < 6; ++f)
        for (int y = 0; y < S; y += 3)  // every third row: the tiles' every row of texels over the run's frames
          for (int x = 0; x < S; ++x)
            ASSERT_EQ(a.bank(e, m).read(f, x, y), b.bank(e, m).read(f, x, y)) << "memory " << m << " eye " << e << " face " << f << " texel " << x << "," << y;
  }
  ASSERT_GT(a.tiles_most_at_once(0), 1);
  // Every memory with one slot: the host hands the balls down to memory 0, which has no faster memory to hand them
  // to, so texels are lost from the first frames, counted, and the run says so once, naming the memory and its
  // slots; the fast cycle level reads the same starved banks and shows the functional level's frames.
  dp::ArpConfig small = p.config;
  small.memory.tile_pool.assign(static_cast<size_t>(M), 1);
  std::ofstream(d.file("small.json")) << config::to_json(small).dump(2);
  nlohmann::json rep[2];
  for (int k = 0; k < 2; ++k) {
    const std::string j = d.file("level" + std::to_string(k) + ".json");
    const auto o = run_command(kArpsim + " run -q --frames 4 --every 0 --error-every 0 --config " + d.file("small.json") + " --scene " +
                               d.file("row.json") + " --walk " + d.file("walk.json") + (k ? " --fidelity cycle" : "") + " --report " + j);
    ASSERT_EQ(o.status, 0) << o.output;
    size_t warnings = 0;
    for (size_t at = o.output.find("want of a tile slot"); at != std::string::npos; at = o.output.find("want of a tile slot", at + 1)) ++warnings;
    EXPECT_EQ(warnings, 1u) << o.output;
    EXPECT_NE(o.output.find("the tile pool of memory 0 (1 slots)"), std::string::npos) << o.output;
    rep[k] = test::load_json(j);
  }
  EXPECT_GT(rep[0]["footprint"]["texels_lost_tile_pool_full"].get<int64_t>(), 0);
  EXPECT_EQ(rep[0]["footprint"]["display_memory_tiles_most_at_once"][0], 1);
  EXPECT_EQ(rep[0]["footprint"]["texels_lost_tile_pool_full"], rep[1]["footprint"]["texels_lost_tile_pool_full"]);
  ASSERT_EQ(rep[0]["frames"].size(), 4u);
  EXPECT_EQ(rep[0]["frames"], rep[1]["frames"]);
  // The command with --fixed-tiles: no pool, the fixed tiles (its default, the pools, is the library's default).
  const auto o = run_command(kArpsim + " plan -q --scene " + d.file("row.json") + " --walk " + d.file("walk.json") +
                             " --threshold-deg 0.5 --keep-widths --objects-only --set display.h_active=160 --set display.v_active=120"
                             " --fixed-tiles -o " + d.file("fixed.json"));
  ASSERT_EQ(o.status, 0) << o.output;
  const dp::ArpConfig c = config::load_file(d.file("fixed.json"));
  EXPECT_EQ(c.memory.tile_pool, fixed.config.memory.tile_pool);
  EXPECT_EQ(c.memory.tiles, fixed.config.memory.tiles);
}

// The plan writes each object's memories over its motion (memory.assignment): one string per name, in the
// scene's order, each the fastest and slowest memory the rule put that object in. A run of the walk with them is
// frame for frame the run without them, nothing held either way (so no range is too narrow); the nearest ball
// reaches memory 0 and the farthest does not. Edited, they bind: the farthest ball pinned to memory 0 is drawn
// at every update of memory 0 (one object more each update and eye, exactly), held faster and not slower; the nearest
// held in the slowest memory is held slower, and the run warns of it once; a name no object has is an error
// naming the key and the scene, and a warning where the plan was made for another scene.
TEST(Planner, TheAssignmentIsWhereTheRulePutsEachObjectAndBindsOnlyWhenEdited) {
  TempDir d;
  PlanRequest r = ball_row(d, 5, [](int i) { return -1.5 * (i + 1); }, 3, 0.5);
  r.base = small_display_60hz();
  r.tile_sparse = false;  // whole faces: an object pinned anywhere has its tiles there
  const Plan p = make_plan(r);
  const int M = p.config.memory.count;
  ASSERT_GT(M, 1);
  ASSERT_EQ(p.config.memory.assignment.size(), 5u);
  std::vector<dp::ObjectAssignment> a;
  std::string why;
  ASSERT_TRUE(dp::object_assignments(p.config.memory, a, why)) << why;
  for (int i = 0; i < 5; ++i) EXPECT_EQ(a[static_cast<size_t>(i)].name, "b" + std::to_string(i));
  EXPECT_EQ(a[0].fastest, 0);
  EXPECT_GT(a[4].fastest, 0);
  EXPECT_EQ(p.assignment.size(), 5u);
  EXPECT_NE(plan_markdown(p, r).find("| b4 | " + std::to_string(a[4].fastest) + " | " + std::to_string(a[4].slowest) + " |"),
            std::string::npos);
  std::ofstream(d.file("plan.json")) << config::to_json(p.config).dump(2);
  dp::ArpConfig none = p.config;
  none.memory.assignment.clear();
  std::ofstream(d.file("none.json")) << config::to_json(none).dump(2);
  const int frames = static_cast<int>(std::ceil(3.0 * dp::VideoTiming(p.config.timing).refresh_hz()));
  const auto run = [&](const std::string& config, const std::string& name, int n) {
    const std::string j = d.file("report-" + name + ".json");
    const auto o = run_command(kArpsim + " run -q --frames " + std::to_string(n) + " --every 0 --error-every 0 --config " + config +
                               " --scene " + d.file("row.json") + " --walk " + d.file("walk.json") + " --report " + j);
    return std::pair{o, o.status == 0 ? test::load_json(j) : nlohmann::json()};
  };
  const auto [o1, with] = run(d.file("plan.json"), "with", frames);
  const auto [o2, without] = run(d.file("none.json"), "without", frames);
  ASSERT_EQ(o1.status, 0) << o1.output;
  ASSERT_EQ(o2.status, 0) << o2.output;
  EXPECT_TRUE(with["frames"] == without["frames"]) << "the frames differ";
  EXPECT_TRUE(with["host"]["memories"] == without["host"]["memories"]) << with["host"]["memories"].dump();
  EXPECT_EQ(with["host"]["object_frames_held_slower_by_assignment"], 0);
  EXPECT_EQ(with["host"]["object_frames_held_faster_by_assignment"], 0);
  EXPECT_EQ(o1.output.find("memory.assignment"), std::string::npos) << o1.output;
  // Edited: b4 pinned to memory 0, b0 held in the slowest.
  const auto edited = [&](const std::string& file, std::vector<std::string> list) {
    dp::ArpConfig c = p.config;
    c.memory.assignment = std::move(list);
    std::ofstream(d.file(file)) << config::to_json(c).dump(2);
    return d.file(file);
  };
  const int n = 30;
  const auto [o3, base] = run(d.file("plan.json"), "base", n);
  const auto [o4, pinned] = run(edited("pinned.json", {"b4: 0"}), "pinned", n);
  ASSERT_EQ(o3.status, 0) << o3.output;
  ASSERT_EQ(o4.status, 0) << o4.output;
  const int64_t updates = pinned["host"]["memories"][0]["updates"].get<int64_t>();
  ASSERT_EQ(updates, base["host"]["memories"][0]["updates"].get<int64_t>());
  EXPECT_NEAR(pinned["host"]["memories"][0]["objects_per_update"].get<double>(),
              base["host"]["memories"][0]["objects_per_update"].get<double>() + 2.0, 1e-9);  // (counted for each eye)
  EXPECT_EQ(pinned["host"]["object_frames_held_faster_by_assignment"], n + 1);  // each frame, and before the first
  EXPECT_EQ(pinned["host"]["object_frames_held_slower_by_assignment"], 0);
  EXPECT_EQ(o4.output.find("warning"), std::string::npos) << o4.output;
  const auto [o5, slow] = run(edited("slow.json", {"b0: " + std::to_string(M - 1)}), "slow", n);
  ASSERT_EQ(o5.status, 0) << o5.output;
  EXPECT_GT(slow["host"]["object_frames_held_slower_by_assignment"].get<int64_t>(), 0);
  size_t warnings = 0;
  for (size_t at = o5.output.find("memory.assignment kept objects"); at != std::string::npos;
       at = o5.output.find("memory.assignment kept objects", at + 1))
    ++warnings;
  EXPECT_EQ(warnings, 1u) << o5.output;
  // Region priority rendering and the baseline place objects themselves: the key is not used, and the run says so.
  // (Regions of 8 m: one column holds the whole row, no ball is cut, so the pinned balls keep their names.)
  for (const std::string mode : {" --regions 8", " --baseline"}) {
    const std::string j = d.file("report-mode.json");
    const auto o = run_command(kArpsim + " run -q --frames 4 --every 0 --error-every 0 --config " + edited("mode.json", {"b0: " + std::to_string(M - 1), "b4: 0"}) +
                               " --scene " + d.file("row.json") + " --walk " + d.file("walk.json") + mode + " --report " + j);
    ASSERT_EQ(o.status, 0) << o.output;
    EXPECT_NE(o.output.find("memory.assignment is not used"), std::string::npos) << mode << o.output;
    const nlohmann::json m = test::load_json(j);
    if (mode == " --regions 8") {
      EXPECT_EQ(m["host"]["regions"]["objects_cut"], 0);  // so the names are the scene's
    }
    EXPECT_EQ(m["host"]["object_frames_held_slower_by_assignment"], 0) << mode;
    EXPECT_EQ(m["host"]["object_frames_held_faster_by_assignment"], 0) << mode;
  }
  // A name no object of the scene has.
  const auto [o6, ghost] = run(edited("ghost.json", {"b1: 1", "ghost: 0"}), "ghost", 2);
  EXPECT_NE(o6.status, 0);
  EXPECT_NE(o6.output.find("ghost.json"), std::string::npos) << o6.output;
  EXPECT_NE(o6.output.find("memory.assignment"), std::string::npos) << o6.output;
  EXPECT_NE(o6.output.find("1 of its names are no object of scene row: \"ghost\""), std::string::npos) << o6.output;
  EXPECT_FALSE(std::filesystem::exists(d.file("report-ghost.json")));
  dp::ArpConfig other = config::load_file(d.file("ghost.json"));
  other.plan.scene_hash = p.scene_hash + 1;
  std::ofstream(d.file("other.json")) << config::to_json(other).dump(2);
  const auto [o7, elsewhere] = run(d.file("other.json"), "elsewhere", 2);
  ASSERT_EQ(o7.status, 0) << o7.output;
  EXPECT_NE(o7.output.find("the plan was made for another scene"), std::string::npos) << o7.output;
}

// On a walk the head faces where it goes, so at a corner it turns, and the eyes with it: the run's rule renders
// the objects it brings beyond theta_t faster there, and the plan replays that turning too. A plan of a walk
// round a corner past balls near and far gives ranges that hold every choice of the run's rule over the walk
// (nothing held either way), and some ball's range reaches a faster memory than walking straight past it
// would: at the corner, and the run held to the ranges of a rule blind to turning wants faster there. (Seen
// failing with the plan's replay given no turning: object-frames held slower; and with the run's given none.)
// Three 0.3 m balls named near, mid and far at `positions` (balls.json in `d`) and a walk (`walk_name` in `d`), planned
// at 60 Hz (a frame of turning at a corner is then about the default's) at theta_t 0.5 deg, the starting widths kept,
// whole faces.
PlanRequest three_balls(TempDir& d, const std::string& positions, const std::string& walk_name, const std::string& walk) {
  std::string objs;
  const char* names[] = {"near", "mid", "far"};
  std::istringstream in(positions);
  for (int i = 0; i < 3; ++i) {
    std::string at;
    std::getline(in, at, ';');
    objs += std::string(i ? ", " : "") + R"({"name": ")" + names[i] + R"(", "sphere": 0.3, "position": )" + at + "}";
  }
  write(d.file("balls.json"), R"({"name": "balls", "objects": [)" + objs + "]}");
  write(d.file(walk_name), walk);
  PlanRequest r = request(d.file("balls.json"), d.file(walk_name));
  r.base = small_display_60hz();
  r.threshold_deg = 0.5;
  r.size_widths = false;
  r.tile_sparse = false;
  return r;
}

TEST(Planner, TheAssignmentHoldsWhatTheRuleDoesAtTheCornersOfAWalk) {
  TempDir d;
  PlanRequest r = three_balls(d, "[1.5, 1.6, -2]; [-3, 1.6, -6]; [-9, 1.6, 2]", "corner.json",
                              R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -3], [3, 1.6, -3]]})");
  const Plan p = make_plan(r);
  ASSERT_GT(p.config.memory.count, 1);
  std::ofstream(d.file("plan.json")) << config::to_json(p.config).dump(2);
  const std::string j = d.file("report.json");
  const int frames = static_cast<int>(5.9 * dp::VideoTiming(p.config.timing).refresh_hz());  // the walk, once (it loops at 6 s)
  const auto o = run_command(kArpsim + " run -q --frames " + std::to_string(frames) + " --every 0 --error-every 0 --config " +
                             d.file("plan.json") + " --scene " + d.file("balls.json") + " --walk " + d.file("corner.json") + " --report " + j);
  ASSERT_EQ(o.status, 0) << o.output;
  const nlohmann::json rep = test::load_json(j);
  EXPECT_EQ(rep["host"]["object_frames_held_slower_by_assignment"], 0) << p.config.memory.assignment.size();
  EXPECT_EQ(rep["host"]["object_frames_held_faster_by_assignment"], 0);
  EXPECT_EQ(o.output.find("memory.assignment"), std::string::npos) << o.output;
  // The turn at the corner: some ball's fastest memory is faster than the rule, blind to turning, would ever put it
  // in over the same walk at the plan's ladder (the scheduler replayed here with no turning, at every frame).
  std::vector<dp::ObjectAssignment> planned;
  std::string why;
  ASSERT_TRUE(dp::object_assignments(p.config.memory, planned, why)) << why;
  ASSERT_EQ(planned.size(), 3u);
  const host::Scene scene = host::load_scene_file(d.file("balls.json"));
  const double hz = dp::VideoTiming(p.config.timing).refresh_hz();
  dp::MemoryConfig rule_only = p.config.memory;
  rule_only.assignment.clear();
  host::PriorityScheduler blind(scene, host::PriorityConfig::of(rule_only, hz), p.config.memory.face_size);
  const host::WalkPath walk = host::load_walk_file(d.file("corner.json"));
  std::vector<int> fastest(3, p.config.memory.count), slowest(3, 0);
  for (int f = 0; f < frames; ++f) {
    blind.assign(walk.position(f / hz), walk.speed(), {}, f / hz);
    for (size_t i = 0; i < 3; ++i) {
      fastest[i] = std::min(fastest[i], blind.rule_choice(i));
      slowest[i] = std::max(slowest[i], blind.rule_choice(i));
    }
  }
  int faster = 0;
  for (size_t i = 0; i < 3; ++i) faster += planned[i].fastest < fastest[i] ? 1 : 0;
  EXPECT_GT(faster, 0) << p.config.memory.assignment.size();
  // And the run turns too: held to the ranges the blind rule gives, it wants a faster memory at the corner.
  dp::ArpConfig held = p.config;
  held.memory.assignment.clear();
  for (size_t i = 0; i < 3; ++i)
    held.memory.assignment.push_back(dp::ObjectAssignment{planned[i].name, fastest[i], slowest[i]}.text());
  std::ofstream(d.file("blind.json")) << config::to_json(held).dump(2);
  const auto ob = run_command(kArpsim + " run -q --frames " + std::to_string(frames) + " --every 0 --error-every 0 --config " +
                              d.file("blind.json") + " --scene " + d.file("balls.json") + " --walk " + d.file("corner.json") + " --report " + j);
  ASSERT_EQ(ob.status, 0) << ob.output;
  EXPECT_GT(test::load_json(j)["host"]["object_frames_held_slower_by_assignment"].get<int64_t>(), 0);
}

// The turn a plan replays is the one a run's host takes before each frame: the frame's start as the run tells it (a
// whole picosecond, rounded down), the orientation held then and a display frame before (the last tracker sample at or
// before each, to the nearest picosecond), the motion generated from a second before the first frame. A constant
// rotation at R sampled every millisecond then turns R x (samples between the two) / 1000 over the frame: at 60 Hz,
// 17 steps every frame (frame 0's frame before is held by the samples before 0; frame 1 starts 1/3 ps before 16 2/3
// ms, so its frame before reaches back past 0 to the sample at -1 ms: with the frame times f / 60 Hz, 16 steps at
// frames 1, 4, 7, 10).
TEST(HeadTurnRate, AConstantRotationTurnsBetweenTheSamplesARunHolds) {
  const host::WalkPath still({{0, 1.6, 0}, {0, 1.6, -1}}, 0.0, "still");
  HeadMotion head;
  head.motion.motion = "rotate";
  head.motion.rate = 300;
  const dp::VideoTiming vt(small_display_60hz().timing);
  const double hz = vt.refresh_hz(), dt = 1.0 / hz;
  ASSERT_EQ(hz, 60.0);
  auto held_ms = [](double s) {  // the sample held at time s: the last whole millisecond at or before it
    const int64_t ps = std::llround(s * 1e12);
    return ps >= 0 ? ps / 1000000000 : -((-ps + 999999999) / 1000000000);
  };
  HeadTurnRate rate(still, head, 1.0);
  int steps_17 = 0;
  for (int64_t f = 0; f < 12; ++f) {
    const double t = vt.frame_start_s(f);
    const int64_t steps = held_ms(t) - held_ms(t - dt);
    steps_17 += steps == 17 ? 1 : 0;
    EXPECT_NEAR(rate.at(t, dt), deg_to_rad(300.0) * static_cast<double>(steps) / 1000.0 / dt, 1e-9) << "frame " << f;
  }
  EXPECT_EQ(steps_17, 12);
}

// The memory a plan updates `object` in, slowest (memory 0 with one memory): its period, in display frames.
int64_t slowest_period_frames(const Plan& p, const std::string& object) {
  const dp::MemoryConfig& m = p.config.memory;
  int slowest = 0;
  std::vector<dp::ObjectAssignment> a;
  std::string why;
  if (!dp::object_assignments(m, a, why)) ADD_FAILURE() << why;
  for (const dp::ObjectAssignment& o : a)
    if (o.name == object) slowest = o.slowest;
  return dp::update_period_frames(m.update_frames, m.update_ratio, slowest);
}

// Standing still, nothing changes: one memory. Turning, the eyes move (IPD/2 either side of the head's centre): a
// 0.3 m ball 1.5 m ahead, d = 1.2 m to its surface, has shifted by theta_t once an eye has moved x = 2 d sin(theta_t
// / 2) (Regan & Pose's translational validity) at omega IPD / 2, its speed on the circle it turns on: every
// x / (omega IPD / 2) = 15.0 frames at 300 deg/s, 2 deg, 60 Hz. The plan's memory 0 updates every power of two of
// frames within the fastest need (docs/planning.md, item 3): 8; with the eyes twice as far apart, 7.5 frames: 4.
TEST(Planner, AHeadTurningStandingStillIsUpdatedAsItsEyesMove) {
  TempDir d;
  write(d.file("ball.json"), R"({"name": "ahead", "objects": [{"name": "ball", "sphere": 0.3, "position": [0, 1.6, -1.5]}]})");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -1]]})");
  PlanRequest r = request(d.file("ball.json"), d.file("walk.json"));
  r.base = small_display_60hz();
  r.walk_speed = 0;
  r.threshold_deg = 2;
  r.size_widths = false;
  const Plan still = make_plan(r);
  r.head.motion.motion = "rotate";
  r.head.motion.rate = 300;
  const Plan turning = make_plan(r);
  const double hz = dp::VideoTiming(r.base.timing).refresh_hz();
  const double x = 2 * (1.5 - 0.3) * std::sin(deg_to_rad(2.0) / 2), eye_speed = deg_to_rad(300.0) * dp::kDefaultIpdM / 2;
  const double need_frames = x / eye_speed * hz;
  ASSERT_NEAR(need_frames, 15.0, 0.05);
  EXPECT_EQ(still.config.memory.count, 1);
  EXPECT_GT(static_cast<double>(slowest_period_frames(still, "ball")), need_frames);
  EXPECT_EQ(turning.config.memory.count, 1);
  EXPECT_EQ(slowest_period_frames(turning, "ball"), 8);
  // Eyes twice as far apart (--ipd) move twice as fast: twice as often.
  r.memories.ipd_m = 2 * dp::kDefaultIpdM;
  const Plan wide = make_plan(r);
  EXPECT_EQ(slowest_period_frames(wide, "ball"), 4);
  // Over the rotation's second (standing_span_s), every frame's turn.
  EXPECT_NEAR(turning.motion_s, 1.0, 1e-9);
  EXPECT_EQ(turning.samples, static_cast<int>(hz) + 1);
  EXPECT_NE(turning.config.plan.motion_hash, still.config.plan.motion_hash);
}

// With a head motion of its own on the walk, the plan replays the turning the run's rule sees (the motion generated
// as a run generates it): a run over that motion keeps within the plan's assignment, where a run of the plan made for
// the walk alone, with the same head motion, wants faster memories than its assignment holds.
TEST(Planner, TheAssignmentHoldsWhatTheRuleDoesWithTheHeadsOwnMotion) {
  TempDir d;
  // Slow enough that the head's shake, not the walk, moves the eyes most: up to 600 deg/s x 32 mm, 0.34 m/s.
  PlanRequest r = three_balls(d, "[1.5, 1.6, -1]; [-3, 1.6, -2]; [-6, 1.6, 1]", "walk.json",
                              R"({"speed": 0.25, "points": [[0, 1.6, 0], [0, 1.6, -0.75]]})");
  const Plan walk_only = make_plan(r);
  r.head.motion.motion = "shake";
  r.head.motion.peak = 600;
  const Plan shaken = make_plan(r);
  ASSERT_GT(walk_only.config.memory.count, 1);
  ASSERT_GT(shaken.config.memory.count, 1);
  const std::string j = d.file("report.json");
  const int frames = static_cast<int>(2.9 * dp::VideoTiming(r.base.timing).refresh_hz());  // the walk, once (it loops at 3 s)
  auto run = [&](const Plan& p) {
    std::ofstream(d.file("plan.json")) << config::to_json(p.config).dump(2);
    const auto o = run_command(kArpsim + " run -q --frames " + std::to_string(frames) + " --every 0 --error-every 0 --config " +
                               d.file("plan.json") + " --scene " + d.file("balls.json") + " --walk " + d.file("walk.json") +
                               " --motion shake --peak 600 --report " + j);
    EXPECT_EQ(o.status, 0) << o.output;
    return std::make_pair(test::load_json(j)["host"], o.output);
  };
  const auto [as_planned, said] = run(shaken);
  EXPECT_EQ(as_planned["object_frames_held_slower_by_assignment"], 0) << shaken.config.memory.assignment.size();
  EXPECT_EQ(as_planned["object_frames_held_faster_by_assignment"], 0);
  EXPECT_EQ(said.find("planned for another motion"), std::string::npos) << said;
  const auto [walk_planned, walk_said] = run(walk_only);
  EXPECT_GT(walk_planned["object_frames_held_slower_by_assignment"].get<int64_t>(), 0);
  EXPECT_NE(walk_said.find("planned for another motion"), std::string::npos) << walk_said;
}

// Objects of one name share one string: its range is the union of theirs, as the same scene with the two
// named apart plans them (a name may hold colons: the string's name ends at its last colon). A plan made from
// that plan plans the same again: the starting configuration's assignment is not kept, and leaves no ladder out.
TEST(Planner, ObjectsOfOneNameShareTheUnionOfTheirMemoriesAndAPlanFromAPlanIsTheSame) {
  TempDir d;
  const auto scene = [&](const std::string& file, const std::string& first, const std::string& second) {
    write(d.file(file), R"({"name": "pair", "objects": [{"name": ")" + first + R"(", "sphere": 0.5, "position": [2, 1.6, -1.5]},
      {"name": "far", "sphere": 0.5, "position": [2, 1.6, -12]},
      {"name": ")" + second + R"(", "sphere": 0.5, "position": [2, 1.6, -40]}]})");
  };
  scene("apart.json", "pair: near", "pair: far");
  scene("shared.json", "pair: x", "pair: x");
  write(d.file("walk.json"), R"({"speed": 1, "points": [[0, 1.6, 0], [0, 1.6, -3]]})");
  const auto plan = [&](const std::string& file, const dp::ArpConfig& base) {
    PlanRequest r = request(d.file(file), d.file("walk.json"));
    r.base = base;
    r.threshold_deg = 0.5;
    r.size_widths = false;
    r.tile_sparse = false;
    r.memory_limit_mib = 0;  // (by default a plan from a plan is held to that plan's memory)
    return make_plan(r);
  };
  const Plan apart = plan("apart.json", small_display()), shared = plan("shared.json", small_display());
  ASSERT_GT(apart.config.memory.count, 1);
  std::vector<dp::ObjectAssignment> a, b;
  std::string why;
  ASSERT_TRUE(dp::object_assignments(apart.config.memory, a, why)) << why;
  ASSERT_TRUE(dp::object_assignments(shared.config.memory, b, why)) << why;
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(a[0].name, "pair: near");
  EXPECT_EQ(a[2].name, "pair: far");
  EXPECT_LT(a[0].slowest, a[2].fastest);  // the near ball is always faster than the far one: the union spans both
  EXPECT_EQ(b[0].name, "pair: x");
  EXPECT_EQ(b[0].fastest, a[0].fastest);
  EXPECT_EQ(b[0].slowest, a[2].slowest);
  EXPECT_EQ(b[1].text(), a[1].text());
  // Planned again from the plan (with more memories than one ladder weighed has).
  const Plan again = plan("apart.json", apart.config);
  EXPECT_EQ(again.ladders.size(), apart.ladders.size());
  EXPECT_EQ(again.config.memory.count, apart.config.memory.count);
  EXPECT_EQ(again.config.memory.assignment, apart.config.memory.assignment);
}

// A tile-sparse memory's bytes in closed form: the default texel is 24 + 16 bits; a bank with 3 tiles holds
// 3 slots of 32 x 32 texels twice (both buffers) and one table of 6 faces x 16 x 16 entries of 2 bits
// (numbers 1 .. 3, and 0 for absent); a bank with none holds nothing; 4 tiles need 3-bit entries. At a face
// size that is no multiple of 32 (100: 4 x 4 tiles, the last 4 texels wide) a tile is still a whole slot.
// Where tiles take less than whole faces, and a configuration's memories held one way and the other.
TEST(Planner, ATileSparseMemorysBytesAreItsTilesTwiceAndOneTable) {
  dp::ArpConfig c;
  ASSERT_EQ(c.memory.face_size, 512);
  EXPECT_EQ(display_memory_bytes_tiled(c, {3, 0}), (2 * 3 * 1024 * 40 + 6 * 16 * 16 * 2 + 7) / 8);
  EXPECT_EQ(display_memory_bytes_tiled(c, {4}), (2 * 4 * 1024 * 40 + 6 * 16 * 16 * 3 + 7) / 8);
  c.memory.face_size = 100;
  EXPECT_EQ(display_memory_bytes_tiled(c, {16}), (2 * 16 * 1024 * 40 + 6 * 4 * 4 * 5 + 7) / 8);
  // Tiles take less than whole faces up to a count in closed form: at 641 texels (21 x 21 tiles a face) and
  // 40-bit texels, a bank of n tiles takes 2 n 1024 x 40 + 6 x 441 x ceil(log2(n + 1)) bits against
  // 2 x 6 x 641^2 x 40: n = 2407 (entries of 12 bits) is the most that takes less.
  c.memory.face_size = 641;
  const int64_t whole_bits = 2 * 6 * int64_t{641} * 641 * 40;
  EXPECT_LT(2 * 2407 * 1024 * 40 + 6 * 441 * 12, whole_bits);
  EXPECT_GT(2 * 2408 * 1024 * 40 + 6 * 441 * 12, whole_bits);
  EXPECT_TRUE(tiles_take_less(c, 2407));
  EXPECT_FALSE(tiles_take_less(c, 2408));
  EXPECT_FALSE(tiles_take_less(c, 6 * 441));
  // A configuration's memories, each as it is held (memory.tiles): two eyes; memory 0 every tile of six faces
  // of 64 texels (whole faces, no table), memory 1 one tile (both buffers of one slot and 6 x 2 x 2 one-bit entries).
  c.memory.face_size = 64;
  c.memory.count = 2;
  c.memory.tiles = {"64:*/*/*/*/*/*", "64:1/-/-/-/-/-"};
  ASSERT_TRUE(dp::validate(c).empty());
  EXPECT_EQ(display_memory_bytes(c), (2 * 2 * 6 * 64 * 64 * 40 + 2 * (2 * 1 * 1024 * 40 + 6 * 2 * 2 * 1) + 7) / 8);
  EXPECT_EQ(tiles_held(c, 0), -1);
  EXPECT_EQ(tiles_held(c, 1), 1);
  c.memory.tiles = {"64:*/*/*/*/*/*", "64:*/*/*/*/*/*"};  // every tile: whole faces, as with no list
  EXPECT_EQ(display_memory_bytes(c), 2 * 2 * 2 * 6 * 64 * 64 * 40 / 8);
  // A tile pool: its slots once (the buffers share them) and a table per buffer -- at 512 texels, 5 slots
  // take 5 x 1024 x 40 bits and two tables of 6 x 16 x 16 entries of 3 bits (1 .. 5 and absent).
  c = dp::ArpConfig{};
  EXPECT_EQ(bank_bits_pooled(c, 5), 5 * 1024 * 40 + 2 * 6 * 16 * 16 * 3);
  EXPECT_EQ(bank_bits_pooled(c, 0), 0);
}

}  // namespace
}  // namespace arp::sim
