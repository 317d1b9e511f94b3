#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <random>

#include "common/InputError.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "reference/golden/GoldenReference.hpp"

using namespace arp::dp;

TEST(OrientationMatrixUnit, IdentityAndQuarterTurnsAreExact) {
  const Mat3q I = quantise_rotation(Quat{1, 0, 0, 0}, 14);
  const int32_t want[9] = {16384, 0, 0, 0, 16384, 0, 0, 0, 16384};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(I.m[i], want[i]);
  // Yaw +90 turns the view left: forward (0,0,-1) becomes (-1,0,0).
  const Mat3q Y = quantise_rotation(normalised(from_yaw_pitch_roll_deg(90, 0, 0), "t"), 14);
  const Vec3q f = rotate(Y, Vec3q{0, 0, -16384}, RotateParams(DatapathWidths{}));
  EXPECT_EQ(f.x, -16384);
  EXPECT_EQ(f.y, 0);
  EXPECT_EQ(f.z, 0);
  // Pitch +90 looks up.
  const Mat3q P = quantise_rotation(normalised(from_yaw_pitch_roll_deg(0, 90, 0), "t"), 14);
  const Vec3q u = rotate(P, Vec3q{0, 0, -16384}, RotateParams(DatapathWidths{}));
  EXPECT_EQ(u.y, 16384);
}

TEST(OrientationMatrixUnit, MatrixEntriesSaturateWhenTheFormatCannotHoldOne) {
  // With a total width of mat_frac+2 bits, 1.0 is representable; rotated
  // outputs saturate at the format's edge rather than wrap.
  DatapathWidths w;
  w.rot_frac = 14;
  const RotateParams p(w);
  Mat3q big{};
  for (int i = 0; i < 9; ++i) big.m[i] = 32767;  // every entry at the top of Q1.14
  const Vec3q r = rotate(big, Vec3q{32767, 32767, 32767}, p);
  EXPECT_EQ(r.x, 32767);
  Mat3q neg{};
  for (int i = 0; i < 9; ++i) neg.m[i] = -32768;
  const Vec3q s = rotate(neg, Vec3q{32767, 32767, 32767}, p);
  EXPECT_EQ(s.x, -32768);
}

TEST(OrientationMatrixUnit, RotationAgreesWithGoldenWithinTheQuantisationBound) {
  const DatapathWidths w;
  const RotateParams p(w);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const Quat q = normalised(Quat{n01(rng), n01(rng), n01(rng), n01(rng)}, "t");
    glm::dvec3 d(n01(rng), n01(rng), n01(rng));
    d = glm::normalize(d);
    const Vec3q dq{static_cast<int32_t>(quantise_real(d.x, 14, 16)), static_cast<int32_t>(quantise_real(d.y, 14, 16)),
                   static_cast<int32_t>(quantise_real(d.z, 14, 16))};
    const Vec3q r = rotate(quantise_rotation(q, 14), dq, p);
    const glm::dvec3 g = arp::golden::rotation(glm::dquat(q.w, q.x, q.y, q.z)) * d;
    for (int k = 0; k < 3; ++k) {
      const int32_t c = k == 0 ? r.x : (k == 1 ? r.y : r.z);
      worst = std::max(worst, std::abs(std::ldexp(c, -14) - g[k]));
    }
  }
  // Three products each off by <= (|m| + |v|) half-LSB, plus the final rounding: < 4 LSB.
  EXPECT_LT(worst, 4.0 * std::ldexp(1.0, -14));
}

TEST(OrientationMatrixUnit, BadQuaternionsAreRejectedWithTheSourceNamed) {
  const double nan = std::nan("");
  EXPECT_THROW(normalised(Quat{0, 0, 0, 0}, "q"), arp::InputError);
  EXPECT_THROW(normalised(Quat{nan, 0, 0, 1}, "q"), arp::InputError);
  EXPECT_THROW(normalised(Quat{1, INFINITY, 0, 0}, "q"), arp::InputError);
  try {
    normalised(Quat{0, 0, 0, 0}, "--quat");
    FAIL();
  } catch (const arp::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--quat"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("zero"), std::string::npos);
  }
  const Quat n = normalised(Quat{2, 0, 0, 0}, "q");
  EXPECT_DOUBLE_EQ(n.w, 1.0);
  const Quat tiny = normalised(Quat{1e-10, 0, 0, 1e-10}, "q");  // tiny but non-zero is fine
  EXPECT_NEAR(tiny.w, std::sqrt(0.5), 1e-12);
}

TEST(OrientationStream, SampleAndHoldWithValidation) {
  const OrientationStream s({{100, Quat{1, 0, 0, 0}}, {200, Quat{0, 1, 0, 0}}, {200, Quat{0, 0, 1, 0}}, {300, Quat{0, 0, 0, 2}}},
                            "trace");
  EXPECT_EQ(s.index_at(0), 0u);    // before the first sample: its value (reset)
  EXPECT_EQ(s.index_at(100), 0u);
  EXPECT_EQ(s.index_at(199), 0u);
  EXPECT_EQ(s.index_at(200), 2u);  // equal times: the later sample wins
  EXPECT_EQ(s.index_at(1'000'000), 3u);
  EXPECT_DOUBLE_EQ(s[3].q.z, 1.0);  // normalised
  try {
    OrientationStream({{100, Quat{}}, {50, Quat{}}}, "trace.csv");
    FAIL();
  } catch (const arp::InputError& e) {
    EXPECT_EQ(e.source(), "trace.csv");
    EXPECT_EQ(e.place(), "sample 1");
  }
  EXPECT_THROW(OrientationStream({{0, Quat{0, 0, 0, 0}}}, "t"), arp::InputError);
  EXPECT_THROW(OrientationStream({}, "t"), arp::InputError);
}

TEST(LatchPolicy, EachPolicySamplesAtItsBoundary) {
  const VideoTiming t{VideoTimingConfig{}};
  auto read = [](const VideoTiming& tt, LatchPolicy p, int64_t lead, int64_t f, int e, int x, int y) {
    return LatchRule(tt, p, lead).read_cycle(f, e, x, y);
  };
  EXPECT_EQ(read(t, LatchPolicy::PerFrame, 0, 2, 0, 100, 300), 840000);
  EXPECT_EQ(read(t, LatchPolicy::PerField, 0, 2, 0, 100, 300), 840000);
  EXPECT_EQ(read(t, LatchPolicy::PerScanline, 0, 2, 0, 100, 300), 840000 + 300 * 800);
  EXPECT_EQ(read(t, LatchPolicy::PerPixel, 0, 2, 0, 100, 300), 840000 + 300 * 800 + 100);
  EXPECT_EQ(read(t, LatchPolicy::PerPixel, 25, 2, 0, 100, 300), 840000 + 300 * 800 + 75);  // pipeline lead
  VideoTimingConfig ic;
  ic.fields_per_frame = 2;
  const VideoTiming ti{ic};
  EXPECT_EQ(read(ti, LatchPolicy::PerField, 0, 0, 0, 5, 7), 210000);
  EXPECT_EQ(read(ti, LatchPolicy::PerFrame, 0, 0, 0, 5, 7), 0);
}

// A latch point is a pixel whose own scan-out slot is the one its group reads
// the register for (lead apart): the closed form the scan logic uses
// (is_latch_point) against that definition, on every pixel of progressive,
// interlaced and side-by-side timings.
TEST(LatchPolicy, LatchPointsAreThePixelsThatStartTheirGroup) {
  VideoTimingConfig prog, inter, sbs;
  for (auto* c : {&prog, &inter, &sbs}) {
    c->h_active = 24;
    c->v_active = 9;
  }
  inter.fields_per_frame = 2;
  inter.v_front_porch = 11;  // an even frame
  sbs.eye_scan = EyeScan::SideBySide;
  int points = 0;
  for (const auto* c : {&prog, &inter, &sbs})
    for (LatchPolicy p : {LatchPolicy::PerFrame, LatchPolicy::PerField, LatchPolicy::PerScanline, LatchPolicy::PerPixel}) {
      const VideoTiming t{*c};
      const LatchRule rule(t, p, 7);
      const int eyes = c->eye_scan == EyeScan::SideBySide ? 2 : 1;  // lock-step eyes share eye 0's slot
      for (int e = 0; e < eyes; ++e)
        for (int y = 0; y < c->v_active; ++y)
          for (int x = 0; x < c->h_active; ++x) {
            const bool starts = rule.read_cycle(3, e, x, y) + 7 == t.pixel_cycle(3, e, x, y);
            EXPECT_EQ(rule.is_latch_point(e, x, y), starts) << to_string(p) << " eye " << e << " (" << x << ", " << y << ")";
            points += starts;
          }
    }
  // frame: 1+1+1, field: 1+2+1, scanline: 9 each, pixel: every pixel (216, 216, 432)
  EXPECT_EQ(points, 3 + 4 + 27 + 864);
}

// A long run keeps only a window of the tracker stream: indices stay those of
// the whole stream, the register's value at the window's start survives, and
// a read before the window is an error rather than a silently wrong sample.
TEST(OrientationStream, DiscardKeepsIndicesAndTheHeldSample) {
  std::vector<OrientationSample> s;
  for (int i = 0; i < 10; ++i) s.push_back({int64_t{1000} * i, Quat{1, 0, 0, 0}});
  OrientationStream st(s, "test");
  st.discard_before(4500);  // samples 0..3 go; 4 (at 4000 ps, held at 4500) stays
  EXPECT_EQ(st.size(), 10u);
  EXPECT_EQ(st.index_at(4500), 4u);
  EXPECT_EQ(st.index_at(4000), 4u);
  EXPECT_EQ(st.index_at(9999), 9u);
  EXPECT_EQ(st[7].time_ps, 7000);
  EXPECT_THROW(st.index_at(3999), std::logic_error);
  st.append({{10000, Quat{0, 0, 1, 0}}}, "test");
  EXPECT_EQ(st.size(), 11u);
  EXPECT_EQ(st.index_at(20000), 10u);
  st.discard_before(4000);  // nothing before the held sample: no change
  EXPECT_EQ(st.index_at(4000), 4u);
}

// The functional model rotates in 32-bit lanes where rotate_fits_int32 says the accumulators fit. At the
// corners of what the register holds (every entry at the ends of mat_frac + 2 bits) and of the lens vectors
// (every component +-max_vec), the largest accumulator magnitude, computed in 64 bits, is within 32 bits
// wherever the check says yes, and rotate_as<int32_t> gives rotate's vector; where it says no (16-bit
// fractions: 3 x 2^17 x 2^16), that magnitude is over.
TEST(OrientationMatrixUnit, ThirtyTwoBitLanesGiveTheSameVectorsWhereTheCheckSaysTheyFit) {
  const struct { int vec_frac, mat_frac, rot_frac; Rounding mode; int64_t max_vec; bool fits; } cases[] = {
      {14, 14, 14, Rounding::HalfUp, int64_t{1} << 14, true},   {7, 6, 8, Rounding::HalfEven, int64_t{1} << 7, true},
      {14, 14, 16, Rounding::Floor, int64_t{1} << 14, true},    {14, 14, 14, Rounding::HalfUp, int64_t{1} << 15, false},
      {16, 16, 14, Rounding::HalfEven, int64_t{1} << 16, false}, {20, 20, 20, Rounding::HalfUp, int64_t{1} << 20, false}};
  for (const auto& c : cases) {
    DatapathWidths w;
    w.vec_frac = c.vec_frac;
    w.mat_frac = c.mat_frac;
    w.rot_frac = c.rot_frac;
    w.rot_rounding = c.mode;
    const bool fits = rotate_fits_int32(w, c.max_vec);
    EXPECT_EQ(fits, c.fits) << "vec_frac " << c.vec_frac << ", mat_frac " << c.mat_frac << ", max_vec " << c.max_vec;
    const RotateParams p(w);
    const int32_t lo = -(int32_t{1} << (c.mat_frac + 1)), hi = (int32_t{1} << (c.mat_frac + 1)) - 1;
    const auto v = static_cast<int32_t>(c.max_vec);
    int64_t widest = 0;
    for (int corner = 0; corner < (1 << 12); ++corner) {  // each of the 9 entries and 3 components at an end
      Mat3q M{};
      for (int i = 0; i < 9; ++i) M.m[i] = corner >> i & 1 ? hi : lo;
      const Vec3q x{corner >> 9 & 1 ? v : -v, corner >> 10 & 1 ? v : -v, corner >> 11 & 1 ? v : -v};
      for (int row = 0; row < 3; ++row) {
        const int64_t sum = int64_t{M.m[3 * row]} * x.x + int64_t{M.m[3 * row + 1]} * x.y + int64_t{M.m[3 * row + 2]} * x.z;
        widest = std::max(widest, (std::abs(sum) << p.shift.left) + p.shift.bias + 1);
      }
      if (!fits) continue;  // (the 32-bit accumulators would overflow: not evaluated)
      const Vec3q a = rotate_as<int32_t>(M, x, p), b = rotate(M, x, p);
      ASSERT_EQ(a.x, b.x);
      ASSERT_EQ(a.y, b.y);
      ASSERT_EQ(a.z, b.z);
    }
    if (fits) EXPECT_LE(widest, INT32_MAX) << "vec_frac " << c.vec_frac << ", mat_frac " << c.mat_frac;
    else EXPECT_GT(widest, INT32_MAX) << "vec_frac " << c.vec_frac << ", mat_frac " << c.mat_frac;
  }
  // Values far inside 32 bits, but a right shift of 32 (vec_frac 24 + mat_frac 14 - rot_frac 6) is undefined
  // for an int32_t: refused. At 31 (rot_frac 7) the shift is defined and the result rotate's (found by a
  // review of 9ec1a61: with Floor rounding and a vector of 1 the check said yes at 32).
  for (const int rot_frac : {6, 7}) {
    DatapathWidths w;
    w.vec_frac = 24;
    w.mat_frac = 14;
    w.rot_frac = rot_frac;
    w.rot_rounding = Rounding::Floor;
    const RotateParams p(w);
    ASSERT_EQ(p.shift.right, 38 - rot_frac);
    EXPECT_EQ(rotate_fits_int32(w, 1), rot_frac == 7);
    if (rot_frac == 6) continue;
    const int32_t lo = -(int32_t{1} << 15), hi = (int32_t{1} << 15) - 1;
    for (int corner = 0; corner < (1 << 12); ++corner) {
      Mat3q M{};
      for (int i = 0; i < 9; ++i) M.m[i] = corner >> i & 1 ? hi : lo;
      const Vec3q x{corner >> 9 & 1 ? 1 : -1, corner >> 10 & 1 ? 1 : -1, corner >> 11 & 1 ? 1 : -1};
      const Vec3q a = rotate_as<int32_t>(M, x, p), b = rotate(M, x, p);
      ASSERT_EQ(a.x, b.x);
      ASSERT_EQ(a.y, b.y);
      ASSERT_EQ(a.z, b.z);
    }
  }
}
