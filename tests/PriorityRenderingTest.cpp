// Object-level priority rendering: validity periods follow the papers'
// formulas at the extremes, objects sort into the memory their validity
// allows and are always in exactly one, walks and the host simulation keep
// their timing rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "common/InputError.hpp"
#include "common/Units.hpp"
#include "host/error/FrameError.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/HostSimulation.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/Primitives.hpp"

using namespace arp;
using namespace arp::host;

TEST(Validity, TranslationalFollowsChowsFormulaAndExtremesAreFinite) {
  const double th = 0.5 * kPi / 180;
  // x = d sqrt(2 (1 - cos th)) over the speed; d is measured to the bound's surface.
  const Validity v = validity({10.5, 0.5, 1.0, 0.0}, th);
  EXPECT_NEAR(v.translational_s, 10.0 * std::sqrt(2 * (1 - std::cos(th))), 1e-12);
  EXPECT_EQ(v.animation_s, kForever);
  EXPECT_NEAR(v.size_s, 0.5 * th * (100 + 0.25) / 0.5, 1e-12);
  // Standing still: nothing changes, forever valid; zero and huge speeds, inside the object.
  EXPECT_EQ(validity({5, 1, 0, 0}, th).period_s(), kForever);
  EXPECT_GT(validity({0, 1, 1e9, 0}, th).period_s(), 0.0);
  EXPECT_TRUE(std::isfinite(validity({0, 0, 1e9, 1e9}, th).period_s()));
  // Spinning at 90 deg/s, radius 1 at 10 m: d th / (r omega).
  EXPECT_NEAR(validity({11, 1, 0, kPi / 2}, th).animation_s, 10 * th / (kPi / 2), 1e-12);
  // Farther means longer valid; a larger threshold too.
  EXPECT_LT(validity({5, 0.5, 1, 0}, th).period_s(), validity({50, 0.5, 1, 0}, th).period_s());
  EXPECT_LT(validity({5, 0.5, 1, 0}, th).period_s(), validity({5, 0.5, 1, 0}, 4 * th).period_s());
}

// A turning head moves the eyes: over a time T an eye half the IPD from the centre, the head turning at omega,
// moves the chord 2 r sin(omega T / 2) -- never more than omega r T nor 2 r (checked against eye_position over
// a sweep of T). Validity is when the eye's displacement, walking at v besides, can first reach the allowed
// x = d sqrt(2 (1 - cos th)) (translational) and (th/2)(d^2 + r^2)/r (size): found here by bisection on
// v T + min(omega r T, 2 r) = x, not by the closed form. Standing and turning, an object whose x is beyond
// the IPD stays valid for ever; one within it, for x / (omega r). No turning gives the figures without it.
// (Seen failing with the reach left out, and with the speed's sum taken as the walk's alone.)
TEST(Validity, TheEyesOfATurningHeadMoveByTheirChordAtMost) {
  const double ipd = 0.064, r = ipd / 2;
  for (const double omega : {0.5, 5.0, 52.36}) {  // rad/s: 29, 286 and 3000 deg/s
    const glm::dvec3 head(1, 1.6, -2);
    const glm::dvec3 e0 = eye_position(head, glm::dquat(1, 0, 0, 0), 0, 2, ipd);
    for (double T = 0.001; T < 2.0; T *= 1.3) {
      const glm::dquat q = glm::angleAxis(omega * T, glm::normalize(glm::dvec3(0.2, 1, 0.1)));
      const double moved = glm::length(eye_position(head, q, 0, 2, ipd) - e0);
      EXPECT_LE(moved, std::min(omega * r * T, 2 * r) + 1e-12) << omega << " " << T;
    }
  }
  const auto solve = [&](double x, double v, double omega) {  // the T where v T + min(omega r T, 2 r) first reaches x
    const auto g = [&](double T) { return v * T + std::min(omega * r * T, 2 * r); };
    double lo = 0, hi = 1;
    while (g(hi) < x) {
      hi *= 2;
      if (hi > 1e12) return kForever;
    }
    for (int i = 0; i < 200; ++i) (g(0.5 * (lo + hi)) < x ? lo : hi) = 0.5 * (lo + hi);
    return hi;
  };
  for (const double th : {0.5 * kPi / 180, 8 * kPi / 180})
    for (const double d : {0.3, 1.0, 3.0, 20.0})
      for (const double v : {0.0, 0.2, 1.0, 5.0})
        for (const double omega : {0.0, 1.0, 5.0, 52.36}) {
          const ValidityInputs in{d + 0.1, 0.1, v, 0};
          const Validity got = validity(in, th, eye_turn(omega, ipd));
          const double xt = d * std::sqrt(2 * (1 - std::cos(th))), xs = 0.5 * th * (d * d + 0.01) / 0.1;
          const double want_t = solve(xt, v, omega), want_s = solve(xs, v, omega);
          const std::string at = "th " + std::to_string(th) + " d " + std::to_string(d) + " v " + std::to_string(v) + " omega " + std::to_string(omega);
          if (want_t == kForever) EXPECT_EQ(got.translational_s, kForever) << at;
          else EXPECT_NEAR(got.translational_s, want_t, 1e-9 * want_t) << at;
          if (want_s == kForever) EXPECT_EQ(got.size_s, kForever) << at;
          else EXPECT_NEAR(got.size_s, want_s, 1e-9 * want_s) << at;
          if (omega == 0) {
            EXPECT_EQ(got.translational_s, validity(in, th).translational_s) << at;
            EXPECT_EQ(got.size_s, validity(in, th).size_s) << at;
          }
        }
  // Standing, turning at 286 deg/s, theta_t 0.5 deg: at 1 m the eye may move 8.7 mm, reached after 8.7 mm / (5 x 32 mm/s);
  // at 10 m, 87 mm: more than the IPD, so for ever. One eye (IPD 0) at the centre: turning moves nothing.
  const double th = 0.5 * kPi / 180;
  EXPECT_NEAR(validity({1.1, 0.1, 0, 0}, th, eye_turn(5, ipd)).translational_s, std::sqrt(2 * (1 - std::cos(th))) / (5 * r), 1e-12);
  EXPECT_EQ(validity({10.1, 0.1, 0, 0}, th, eye_turn(5, ipd)).translational_s, kForever);
  EXPECT_EQ(validity({1.1, 0.1, 0, 0}, th, eye_turn(5, 0)).period_s(), kForever);
}

// The head's turn rate over the frame before t: a constant rotation gives its rate, a still head exactly 0,
// and a walk facing where it goes turns by the corner's angle within the frame that holds the corner.
TEST(WalkPath, TheHeadsTurnRateIsTheAngleTurnedOverTheFrame) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 1, -0.2));
  for (const double w : {0.1, 5.0, 52.36})
    EXPECT_NEAR(turn_rate_rad_s([&](double t) { return glm::angleAxis(w * t, axis); }, 3.0, 1.0 / 60), w, 1e-9 * w) << w;
  EXPECT_EQ(turn_rate_rad_s([](double) { return glm::angleAxis(0.7, glm::dvec3(0, 1, 0)); }, 1.0, 1.0 / 60), 0.0);
  const WalkPath w({{0, 0, 0}, {0, 0, -3}, {3, 0, -3}}, 1.0, "corner");  // ahead 3 m, then a right turn
  EXPECT_EQ(turn_rate_rad_s([&](double t) { return w.facing(t); }, 2.0, 1.0 / 60), 0.0);
  EXPECT_NEAR(turn_rate_rad_s([&](double t) { return w.facing(t); }, 3.01, 1.0 / 60), (kPi / 2) * 60, 1e-6);
  EXPECT_NEAR(glm::length(w.facing(1.0) * glm::dvec3(0, 0, -1) - glm::dvec3(0, 0, -1)), 0, 1e-12);  // looks down -z
  EXPECT_NEAR(glm::length(w.facing(4.0) * glm::dvec3(0, 0, -1) - glm::dvec3(1, 0, 0)), 0, 1e-12);   // then +x
  // An open path jumps from its end to its start: at the jump the walker faces along the path, not back across it.
  // (Seen failing with the difference taken across the jump.)
  for (const double t : {0.0, 1e-4, 6.0, -6.0})
    EXPECT_NEAR(glm::length(w.facing(t) * glm::dvec3(0, 0, -1) - glm::dvec3(0, 0, -1)), 0, 1e-9) << t;
  for (const double t : {6.0 - 1e-4, 12.0 - 1e-4, -1e-4})
    EXPECT_NEAR(glm::length(w.facing(t) * glm::dvec3(0, 0, -1) - glm::dvec3(1, 0, 0)), 0, 1e-9) << t;
}

TEST(PriorityScheduler, ObjectsGoToTheSlowestMemoryTheirValidityAllowsAndToOneOnly) {
  Scene s;
  auto ball = std::make_shared<Mesh>(make_sphere(0.1, 8));
  for (int i = 0; i < 200; ++i) add_object(s, "ball", ball, {0, 0, -0.5 - 0.25 * i}, {});
  PriorityConfig pc;
  pc.threshold_rad = 0.5 * kPi / 180;
  PriorityScheduler sch(s, pc, 512);
  EXPECT_EQ(sch.frames_per_update(0), 1);
  EXPECT_EQ(sch.frames_per_update(3), 8);
  for (double t = 0; t < 2; t += 0.25) {
    const glm::dvec3 eye{0, 0, -10 * t};  // walking into the row of balls at 5 m/s
    sch.assign(eye, 5.0, {}, t);
    sch.settle();
    size_t total = 0;
    for (int m = 0; m < 4; ++m) total += sch.objects_in(m).size();
    EXPECT_EQ(total, s.objects.size());  // each object in exactly one memory
    for (size_t i = 0; i < s.objects.size(); ++i) {
      const int m = sch.memory_of(i);
      const Sphere b = s.objects[i].world_bound(t);
      const double p = validity({glm::length(b.center - eye), b.radius, 5.0, 0}, pc.threshold_rad).period_s();
      if (m > 0) {
        EXPECT_LE(sch.period_s(m), p);
      }
      if (m < 3) {
        EXPECT_GT(sch.period_s(m + 1), p);
      }
    }
  }
  // move() counts what changes; settle() (before a run) does not.
  sch.assign({0, 0, 50}, 5.0, {}, 0);
  for (size_t i = 0; i < s.objects.size(); ++i) sch.move(i);
  EXPECT_GT(sch.moves(), 0);
  // The baseline: everything in memory 0, every frame.
  pc.baseline = true;
  PriorityScheduler base(s, pc, 512);
  base.assign({0, 0, 0}, 1.0, {}, 0);
  EXPECT_EQ(base.objects_in(0).size(), s.objects.size());
  EXPECT_EQ(base.frames_per_update(3), 1);
}

// Where memories hold only some tiles: an object goes to the slowest memory at or below its rule's choice that
// holds its tiles, and where none does, to the rule's choice. Standing still, every ball's rule says the
// slowest memory (3); here memory 3 holds only the even balls' tiles, memory 2 the balls of index 1 mod 4,
// memories 1 and 0 every tile but ball 7's.
TEST(PriorityScheduler, AnObjectGoesNoSlowerThanAMemoryHoldingItsTiles) {
  Scene s;
  auto ball = std::make_shared<Mesh>(make_sphere(0.1, 8));
  for (int i = 0; i < 8; ++i) add_object(s, "ball", ball, {0, 0, -2.0 - i}, {});
  PriorityScheduler sch(s, PriorityConfig{}, 512);
  sch.set_fits([](size_t i, int m, const glm::dvec3&, double) {
    if (i == 7) return false;
    return m == 3 ? i % 2 == 0 : m == 2 ? i % 4 == 1 : true;
  });
  sch.assign({0, 0, 0}, 0.0, {}, 0);
  const std::array<int, 8> want{3, 2, 3, 1, 3, 2, 3, 3};  // ball 7 fits none: the rule's choice
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sch.belongs_in(i), want[i]) << i;
    EXPECT_EQ(sch.rule_choice(i), 3) << i;
    EXPECT_EQ(sch.fits(i, 0, {}, 0), i != 7) << i;
  }
}

// memory.assignment bounds the rule: each object's memory is the rule's choice clamped to its name's range, worked
// out here from the validity formula (the slowest memory m whose period 2^m / 60 s is within it). Walking at 5 m/s,
// a near ball's rule is memory 0 and a far one's memory 3; every "mid" ball, whatever its rule, stays in 1 .. 2.
TEST(PriorityScheduler, ObjectsNamedInTheAssignmentStayInTheirMemories) {
  Scene s;
  auto ball = std::make_shared<Mesh>(make_sphere(0.1, 8));
  add_object(s, "near", ball, {0, 0, -0.5}, {});
  add_object(s, "far", ball, {0, 0, -80}, {});
  for (int i = 0; i < 100; ++i) add_object(s, "mid", ball, {0, 0, -0.5 - 0.5 * i}, {});  // to 50 m: rules 0 .. 2
  add_object(s, "free", ball, {0, 0, -60}, {});
  add_object(s, "free", ball, {0, 0, -200}, {});  // the rule's slowest: at its range's end, not past it
  PriorityConfig pc;
  pc.threshold_rad = 0.5 * kPi / 180;
  for (const char* a : {"near: 2-3", "far: 0", "mid: 1-2", "ghost: 1"}) {
    dp::ObjectAssignment e;
    std::string why;
    ASSERT_TRUE(dp::ObjectAssignment::parse(a, 4, e, why)) << why;
    pc.assignment.push_back(e);
  }
  PriorityScheduler sch(s, pc, 512);
  EXPECT_EQ(sch.unknown_names(), std::vector<std::string>{"ghost"});
  const auto range = [&](size_t i) {
    const std::string& n = s.objects[i].name;
    return n == "near" ? std::pair{2, 3} : n == "far" ? std::pair{0, 0} : n == "mid" ? std::pair{1, 2} : std::pair{0, 3};
  };
  int64_t slower = 0, faster = 0;
  bool near_rule_fast = false, far_rule_slow = false, mid_at_end = false, free_at_end = false;
  for (double t = 0; t < 1; t += 0.125) {
    const glm::dvec3 eye{0, 0, -5 * t};
    sch.assign(eye, 5.0, {}, t);
    for (size_t i = 0; i < s.objects.size(); ++i) {
      const Sphere b = s.objects[i].world_bound(t);
      const double p = validity({glm::length(b.center - eye), b.radius, 5.0, 0}, pc.threshold_rad).period_s();
      int rule = 0;
      while (rule < 3 && std::pow(2.0, rule + 1) / 60.0 <= p) ++rule;
      const auto [lo, hi] = range(i);
      slower += rule < lo ? 1 : 0;
      faster += rule > hi ? 1 : 0;
      near_rule_fast = near_rule_fast || (i == 0 && rule == 0);
      far_rule_slow = far_rule_slow || (i == 1 && rule == 3);
      mid_at_end = mid_at_end || (s.objects[i].name == "mid" && rule == 2);
      free_at_end = free_at_end || (s.objects[i].name == "free" && rule == 3);
      EXPECT_EQ(sch.belongs_in(i), std::clamp(rule, lo, hi)) << i << " at " << t;
      EXPECT_EQ(sch.fastest_allowed(i), lo);
      EXPECT_EQ(sch.slowest_allowed(i), hi);
    }
  }
  EXPECT_TRUE(near_rule_fast && far_rule_slow);  // the clamps bite both ways
  EXPECT_TRUE(mid_at_end && free_at_end);         // and rules at a range's end are not counted
  EXPECT_GE(slower, 8);  // (near: every step)
  EXPECT_GE(faster, 8);  // (far: every step)
  EXPECT_EQ(sch.held_slower(), slower);
  EXPECT_EQ(sch.held_faster(), faster);
  // The baseline places every object itself: memory 0, the assignment not used.
  pc.baseline = true;
  PriorityScheduler base(s, pc, 512);
  base.assign({0, 0, 0}, 5.0, {}, 0);
  for (size_t i = 0; i < s.objects.size(); ++i) EXPECT_EQ(base.belongs_in(i), 0) << i;
  EXPECT_EQ(base.held_slower() + base.held_faster(), 0);
}

TEST(WalkPath, WalksAtItsSpeedLoopsAndRefusesDegeneratePaths) {
  const WalkPath w({{0, 0, 0}, {3, 0, 0}, {3, 0, -4}}, 1.0, "test");
  EXPECT_DOUBLE_EQ(w.length(), 7.0);
  EXPECT_NEAR(glm::length(w.position(2.0) - glm::dvec3(2, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::length(w.position(5.0) - glm::dvec3(3, 0, -2)), 0, 1e-12);
  EXPECT_NEAR(glm::length(w.position(7.0 + 1.0) - w.position(1.0)), 0, 1e-12);  // loops
  EXPECT_NEAR(glm::length(w.velocity(1.0)), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(w.position(3600.0 * 1 + 0.5) - w.position(0.5 + 3600.0 - 7.0 * 514)), 0, 1e-6);  // an hour in
  EXPECT_THROW(WalkPath({{0, 0, 0}}, 1.0, "one point"), InputError);
  EXPECT_THROW(WalkPath({{1, 1, 1}, {1, 1, 1}}, 1.0, "zero length"), InputError);
  EXPECT_THROW(WalkPath({{0, 0, 0}, {1, 0, 0}}, -0.5, "negative speed"), InputError);
  EXPECT_THROW(WalkPath({{0, 0, 0}, {1, 0, 0}}, 1000.5, "past 1000 m/s"), InputError);
  const WalkPath standing({{0, 1, 2}, {1, 0, 0}}, 0.0, "0 m/s: standing at the first point");
  EXPECT_EQ(standing.position(3600.0), glm::dvec3(0, 1, 2));
  EXPECT_EQ(standing.velocity(3600.0), glm::dvec3(0));
  EXPECT_THROW(WalkPath({{0, 0, 0}, {NAN, 0, 0}}, 1.0, "nan"), InputError);
  // Stereo eyes: IPD apart along the head's x axis, which yaw turns.
  const glm::dquat yaw90 = glm::angleAxis(kPi / 2, glm::dvec3(0, 1, 0));
  const glm::dvec3 l = eye_position({0, 1.6, 0}, yaw90, 0, 2, 0.064), r = eye_position({0, 1.6, 0}, yaw90, 1, 2, 0.064);
  EXPECT_NEAR(glm::length(r - l), 0.064, 1e-12);
  EXPECT_NEAR(l.z, 0.032, 1e-12);  // turned left, the left eye is toward +z
}

TEST(HostSimulation, MemoriesUpdateAtTheirRatesAndAnOverloadedEngineKeepsTheOldImage) {
  const Scene g = make_gallery({"/nonexistent"});  // spheres for exhibits: quick
  dp::MemoryConfig mc;
  mc.face_size = 64;
  int64_t moves = 0;
  auto run = [&](double tri_rate, bool baseline) {
    dp::DisplayMemorySet mem(mc, 2);
    PriorityConfig pc;
    pc.threshold_rad = 2 * kPi / 180;
    pc.baseline = baseline;
    RenderEngine e;
    e.triangles_per_s = tri_rate;
    HostSimulation h(g, pc, e, WalkPath(gallery_walk(), 3.0, "walk"), [](double) { return glm::dquat(1, 0, 0, 0); },
                     mem, 0.064, 60.0);
    h.prime(0);
    for (int f = 0; f < 32; ++f) {
      h.before_frame(f, f / 60.0);
      // On screen, every object is in exactly one memory's image at every frame.
      std::vector<int> seen(g.objects.size(), 0);
      for (int m = 0; m < 4; ++m)
        for (size_t i : h.shown_objects(m)) ++seen[i];
      for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "object " << i << " frame " << f;
    }
    moves = h.scheduler().moves();
    return std::vector<MemoryLoad>(h.load());
  };
  const auto fast = run(1e9, false);
  EXPECT_GT(moves, 0);  // walking at 3 m/s, objects changed memory (and the invariant held)
  EXPECT_EQ(fast[0].updates, 32);  // 60 Hz
  EXPECT_GE(fast[1].updates, 16);  // 30 Hz, plus the re-renders of objects changing memory
  EXPECT_GE(fast[2].updates, 8);   // 15 Hz
  EXPECT_GE(fast[3].updates, 4);   // 7.5 Hz
  for (const auto& m : fast) EXPECT_EQ(m.skipped, 0);
  const auto slow = run(1e5, true);  // far too slow: most updates are skipped, the old image stays
  EXPECT_GT(slow[0].skipped, 20);
  EXPECT_GE(slow[0].updates, 1);
  EXPECT_EQ(slow[1].updates, 0);  // the baseline uses memory 0 only
}

TEST(FrameError, PsnrAndDisplacement) {
  HmdFrame a, b;
  a.resize(4, 4, 1, false);
  b.resize(4, 4, 1, false);
  EXPECT_TRUE(std::isinf(image_error(a, b).psnr_db));
  b.pixels[0] = 0xff0000;  // one channel of one pixel off by 255
  const ImageError e = image_error(a, b);
  EXPECT_NEAR(e.mse, 255.0 * 255.0 / 48.0, 1e-9);
  EXPECT_NEAR(e.psnr_db, 10 * std::log10(48.0), 1e-9);
  EXPECT_NEAR(e.differing, 1.0 / 16, 1e-12);
  EXPECT_NEAR(displacement_rad({0, 0, 0}, {0, 0, -1}, {0, 0, 0}, {1, 0, -1}), kPi / 4, 1e-12);
  EXPECT_EQ(displacement_rad({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}), 0.0);
}

// The mean of each n x n block, channel by channel, rounded to the nearest code (halves up): worked by hand.
TEST(FrameError, AreaMeanAveragesEachBlockOfSamplesChannelByChannel) {
  HmdFrame fine;
  fine.resize(4, 2, 1, false);
  // Left block: red 10, 11, 12, 14 (mean 11.75 -> 12); green 0, 0, 0, 1 (0.25 -> 0); blue 255 x 4.
  // Right block: red 1, 2, 0, 0 (0.75 -> 1); green 1, 1, 0, 0 (0.5 -> 1, a half rounds up); blue 0.
  const uint32_t px[2][4] = {{0x0a00ff, 0x0b00ff, 0x010100, 0x020100}, {0x0c00ff, 0x0e01ff, 0x000000, 0x000000}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) fine.pixels[fine.index(0, x, y)] = px[y][x];
  const HmdFrame out = area_mean(fine, 2);
  ASSERT_EQ(out.width, 2);
  ASSERT_EQ(out.height, 1);
  EXPECT_EQ(out.pixels[0], 0x0c00ffu);
  EXPECT_EQ(out.pixels[1], 0x010100u);
}

// When objects change memory: only at frames where the memories are due
// anyway. Walking away from a row of balls, objects go to slower memories and
// every memory renders exactly on its schedule, no more (moves used to force
// renders). Walking into the row, they go to faster ones in time: at every
// frame each object's image on screen is within the validity it had when it
// was rendered (Validity's closed form, evaluated here), give or take the
// frame its replacement takes to swap in.
TEST(HostSimulation, ObjectsChangeMemoryOnScheduleAndStayWithinTheirValidity) {
  Scene s;
  auto ball = std::make_shared<Mesh>(make_sphere(0.1, 6));
  for (int i = 0; i < 40; ++i) add_object(s, "ball", ball, {0, 1.6, -1.0 - 0.5 * i}, {});
  const double th = 2 * kPi / 180, hz = 60;
  dp::MemoryConfig mc;
  mc.face_size = 32;
  auto run = [&](const std::vector<glm::dvec3>& path, double speed, int frames) {
    dp::DisplayMemorySet mem(mc, 2);
    PriorityConfig pc;
    pc.threshold_rad = th;
    HostSimulation h(s, pc, RenderEngine{}, WalkPath(path, speed, "row"), [](double) { return glm::dquat(1, 0, 0, 0); },
                     mem, 0.064, hz);
    h.prime(0);
    double worst_overrun_s = -1e9;
    for (int f = 0; f < frames; ++f) {
      const double t = f / hz;
      h.before_frame(f, t);
      for (size_t i = 0; i < s.objects.size(); ++i) {
        const int m = h.shown_in(i);
        const double then = h.rendered_at(m);
        const glm::dvec3 eye_then = WalkPath(path, speed, "row").position(then);
        const double d = glm::length(s.objects[i].world_bound(then).center - eye_then);
        const double valid = validity({d, 0.1, speed, 0}, th).period_s();
        worst_overrun_s = std::max(worst_overrun_s, (t - then) - valid);
      }
    }
    return std::pair{std::vector<MemoryLoad>(h.load()), worst_overrun_s};
  };
  // Away from the row at 2 m/s for 96 frames: validity only grows.
  const auto [away, away_overrun] = run({{0, 1.6, 0}, {0, 1.6, 40}}, 2.0, 96);
  for (int m = 0; m < 4; ++m) EXPECT_EQ(away[static_cast<size_t>(m)].updates, 96 >> m) << "memory " << m;
  EXPECT_LE(away_overrun, 1.0 / hz);
  // Into the row at 4 m/s: validity shrinks; objects leave slow memories in time.
  const auto [into, into_overrun] = run({{0, 1.6, 0}, {0, 1.6, -40}}, 4.0, 96);
  EXPECT_LE(into_overrun, 1.0 / hz);
  EXPECT_GT(into[3].updates, 0);
}
