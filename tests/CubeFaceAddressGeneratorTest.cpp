#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "reference/golden/GoldenReference.hpp"

using namespace arp::dp;

namespace {
Vec3q q14(double x, double y, double z) {
  return {static_cast<int32_t>(quantise_real(x, 14, 16)), static_cast<int32_t>(quantise_real(y, 14, 16)),
          static_cast<int32_t>(quantise_real(z, 14, 16))};
}
}  // namespace

TEST(CubeFaceAddressGenerator, AxisDirectionsHitFaceCentres) {
  const AddressGeneratorParams p(DatapathWidths{}, 512);
  const struct { Vec3q v; int face; } cases[] = {{q14(1, 0, 0), kPosX}, {q14(-1, 0, 0), kNegX}, {q14(0, 1, 0), kPosY},
                                                 {q14(0, -1, 0), kNegY}, {q14(0, 0, 1), kPosZ}, {q14(0, 0, -1), kNegZ}};
  for (const auto& c : cases) {
    const CubeAddress a = generate_address(c.v, p);
    EXPECT_EQ(a.face, c.face);
    EXPECT_EQ(a.x, 256);
    EXPECT_EQ(a.y, 256);
    EXPECT_EQ(a.fx, 0u);
    EXPECT_EQ(a.u, 256 << 8);
  }
}

TEST(CubeFaceAddressGenerator, FollowsTheOpenGLTableOnEveryFace) {
  // Each face, a direction off-centre toward +s and +t per the GL table, must land at s, t > 0.5.
  const AddressGeneratorParams p(DatapathWidths{}, 512);
  const double a = 0.3, b = 0.2;
  const struct { double x, y, z; int face; } cases[] = {
      {1, -b, -a, kPosX}, {-1, -b, a, kNegX}, {a, 1, b, kPosY}, {a, -1, -b, kNegY}, {a, -b, 1, kPosZ}, {-a, -b, -1, kNegZ}};
  for (const auto& c : cases) {
    const double n = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    const CubeAddress ad = generate_address(q14(c.x / n, c.y / n, c.z / n), p);
    EXPECT_EQ(ad.face, c.face);
    EXPECT_NEAR(ad.u / 256.0, (a + 1) / 2 * 512, 0.1) << face_name(c.face);
    EXPECT_NEAR(ad.v / 256.0, (b + 1) / 2 * 512, 0.1) << face_name(c.face);
  }
}

TEST(CubeFaceAddressGenerator, TieRuleXBeforeYBeforeZOnEdgesAndCorners) {
  const AddressGeneratorParams p(DatapathWidths{}, 512);
  EXPECT_EQ(generate_address(Vec3q{1000, 1000, 0}, p).face, kPosX);
  EXPECT_EQ(generate_address(Vec3q{-1000, 1000, 0}, p).face, kNegX);
  EXPECT_EQ(generate_address(Vec3q{0, 1000, 1000}, p).face, kPosY);
  EXPECT_EQ(generate_address(Vec3q{0, -1000, 1000}, p).face, kNegY);
  EXPECT_EQ(generate_address(Vec3q{1000, 0, -1000}, p).face, kPosX);
  EXPECT_EQ(generate_address(Vec3q{1000, 1000, 1000}, p).face, kPosX);
  EXPECT_EQ(generate_address(Vec3q{-1000, -1000, -1000}, p).face, kNegX);
  // On an edge the two faces meet at their shared border: s or t at the face edge.
  const CubeAddress e = generate_address(Vec3q{9459, 9459, 9459}, p);  // corner, major 1/sqrt3
  EXPECT_EQ(e.face, kPosX);
  EXPECT_EQ(e.x, 0);     // sc = -z = -|ma| -> s = 0
  EXPECT_EQ(e.y, 0);     // tc = -y -> t = 0
  // Golden uses the same rule.
  EXPECT_EQ(arp::golden::address(glm::dvec3(1, 1, 1), 512).face, kPosX);
  EXPECT_EQ(arp::golden::address(glm::dvec3(0, -1, 1), 512).face, kNegY);
  EXPECT_EQ(arp::golden::address(glm::dvec3(-0.0, 0.0, -0.0), 512).face, kPosX);
}

TEST(CubeFaceAddressGenerator, ZeroVectorAddressesTheFaceCentreWithoutDividingByZero) {
  const AddressGeneratorParams p(DatapathWidths{}, 512);
  const CubeAddress a = generate_address(Vec3q{0, 0, 0}, p);
  EXPECT_EQ(a.face, kPosX);
  EXPECT_EQ(a.x, 256);
  DatapathWidths w;
  w.divider = DividerKind::Exact;
  EXPECT_EQ(generate_address(Vec3q{0, 0, 0}, AddressGeneratorParams(w, 512)).x, 256);
}

TEST(ReciprocalUnit, LutWithNewtonStepIsAccurateOverTheWholeRange) {
  // Every major component a Q1.14 unit vector can have (1/sqrt3 .. 1 and
  // beyond, up to the format's edge), and the values below it.
  for (int newton : {0, 1, 2}) {
    const auto table = build_reciprocal_table(8, 16);
    ReciprocalParams p;
    p.lut = table.data();
    p.index_bits = 8;
    p.recip_frac = 16;
    p.newton_steps = newton;
    p.rounding = RoundingSel(Rounding::HalfUp);
    double worst = 0.0;
    for (int64_t m = 1; m < 32768; ++m) {
      const Reciprocal r = reciprocal(m, p);
      const double got = std::ldexp(static_cast<double>(r.y), 1 - r.n - 16);  // 1/m in units of 2^-0
      worst = std::max(worst, std::abs(got * static_cast<double>(m) - 1.0));
    }
    // A 256-entry midpoint table: relative error <= half an interval, 2^-9,
    // plus the entry's own rounding (2^-17); a Newton step squares it, leaving
    // the Q1.16 rounding of the result.
    const double bound = newton == 0 ? std::ldexp(1.0, -9) + std::ldexp(1.0, -17) : std::ldexp(1.0, -14);
    EXPECT_LE(worst, bound) << "newton steps " << newton;
  }
}

TEST(ReciprocalUnit, ExactDividerRoundsAsConfigured) {
  const RoundingSel up(Rounding::HalfUp), even(Rounding::HalfEven), fl(Rounding::Floor);
  // 3/2 = 1.5 in Q.0: half up 2, half even 2, floor 1; 5/2 = 2.5: even 2.
  EXPECT_EQ(divide_exact(3, 2, 0, up), 2);
  EXPECT_EQ(divide_exact(3, 2, 0, even), 2);
  EXPECT_EQ(divide_exact(3, 2, 0, fl), 1);
  EXPECT_EQ(divide_exact(5, 2, 0, even), 2);
  EXPECT_EQ(divide_exact(-3, 2, 0, up), -1);
  EXPECT_EQ(divide_exact(-3, 2, 0, fl), -2);
  EXPECT_EQ(divide_exact(-5, 2, 0, even), -2);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int64_t> dm(9459, 16390), ds(-16390, 16390);
  for (int i = 0; i < 100000; ++i) {
    const int64_t m = dm(rng), s = ds(rng);
    const long double q = std::ldexp(static_cast<long double>(s), 16) / static_cast<long double>(m);
    ASSERT_EQ(divide_exact(s, m, 16, fl), static_cast<int64_t>(std::floor(q)));
    ASSERT_LE(std::abs(static_cast<long double>(divide_exact(s, m, 16, up)) - q), 0.5L);
  }
}

TEST(CubeFaceAddressGenerator, LutAndExactDividersAgreeWithinOneTexelFraction) {
  DatapathWidths w;
  const AddressGeneratorParams lut(w, 512);
  w.divider = DividerKind::Exact;
  const AddressGeneratorParams ex(w, 512);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n01;
  int64_t worst = 0;
  for (int i = 0; i < 200000; ++i) {
    glm::dvec3 d = glm::normalize(glm::dvec3(n01(rng), n01(rng), n01(rng)));
    const Vec3q v = q14(d.x, d.y, d.z);
    const CubeAddress a = generate_address(v, lut), b = generate_address(v, ex);
    ASSERT_EQ(a.face, b.face);
    worst = std::max({worst, std::abs(a.u - b.u), std::abs(a.v - b.v)});
  }
  EXPECT_LE(worst, 2);  // in 1/256 texel
}

TEST(CubeFaceAddressGenerator, PositionsClampToTheFaceAndNonPowerOfTwoFacesWork) {
  const AddressGeneratorParams p(DatapathWidths{}, 300);
  // s = 1 exactly (sc = +|ma|): clamped to the last texel, fraction at its top.
  const CubeAddress a = generate_address(Vec3q{16384, -16384, -16384}, p);  // +X, sc = -z = +16384
  EXPECT_EQ(a.face, kPosX);
  EXPECT_EQ(a.x, 299);
  EXPECT_EQ(a.fx, 255u);
  EXPECT_EQ(a.y, 299);
  const CubeAddress c = generate_address(Vec3q{16384, 0, 0}, p);
  EXPECT_EQ(c.x, 150);
}

TEST(ReciprocalUnit, AlignedReciprocalGivesTheSameQuotientsAsTheNormalisedOne) {
  // Every |ma| of the format, |sc| <= |ma| at both ends, zero and spread
  // between, for each rounding mode and several unit configurations
  // (including quotient shifts that become left shifts).
  std::mt19937_64 rng(17);
  const struct { int rot_frac, index_bits, recip_frac, newton, quot_frac; } units[] = {
      {14, 8, 16, 1, 16}, {14, 4, 8, 0, 9}, {10, 6, 20, 2, 30}, {7, 3, 5, 0, 2}, {15, 10, 16, 1, 16}};
  for (const auto& u : units)
    for (Rounding mode : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
      const auto table = build_reciprocal_table(u.index_bits, u.recip_frac);
      ReciprocalParams p;
      p.lut = table.data();
      p.index_bits = u.index_bits;
      p.recip_frac = u.recip_frac;
      p.newton_steps = u.newton;
      p.rounding = RoundingSel(mode);
      const int n_max = u.rot_frac + 1;
      for (int64_t m = 1; m < (int64_t{1} << n_max); ++m) {
        const Reciprocal r = reciprocal(m, p);
        const int64_t ya = aligned_reciprocal(r, n_max);
        std::uniform_int_distribution<int64_t> d(-m, m);
        for (int64_t sc : {m, -m, int64_t{0}, int64_t{1}, int64_t{-1}, d(rng), d(rng), d(rng)}) {
          ASSERT_EQ(multiply_aligned_reciprocal(sc, ya, u.recip_frac, n_max, u.quot_frac, p.rounding),
                    multiply_reciprocal(sc, r, u.recip_frac, u.quot_frac, p.rounding))
              << "m=" << m << " sc=" << sc << " mode=" << to_string(mode) << " rot_frac=" << u.rot_frac;
        }
      }
    }
}

// The functional model computes the generator in 32-bit lanes where address_fits_int32 says every value
// fits. Checked here by enumeration, not by the check's closed form: for every |ma| the table covers, with
// sc at both ends, zero, one and spread between, in every rounding mode and several unit configurations,
// the 64-bit chain's widest values (the product and its rounding bias, the position before its shift) stay
// within 32 bits wherever the check says yes, and the 32-bit chain gives the same quotient and position.
// Where a value does not fit -- quotients of 24 fraction bits on a face of 512 texels, (q + 1) S reaches
// 2^34 -- the check says no.
TEST(CubeFaceAddressGenerator, ThirtyTwoBitLanesGiveTheSamePositionsWhereTheCheckSaysTheyFit) {
  std::mt19937_64 rng(23);
  const struct { int rot_frac, index_bits, recip_frac, quot_frac, texel_frac, face; bool fits; } units[] = {
      {14, 8, 16, 16, 8, 512, true},  {14, 8, 16, 16, 8, 300, true}, {8, 3, 8, 9, 3, 512, true},
      {15, 10, 15, 16, 8, 2048, true}, {14, 8, 16, 24, 12, 512, false}, {14, 8, 16, 16, 8, 1 << 14, false}};
  for (const auto& u : units)
    for (Rounding mode : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
      DatapathWidths w;
      w.rot_frac = u.rot_frac;
      w.recip_index_bits = u.index_bits;
      w.recip_frac_bits = u.recip_frac;
      w.quot_frac = u.quot_frac;
      w.texel_frac = u.texel_frac;
      w.div_rounding = w.texel_rounding = mode;
      const AddressGeneratorParams p(w, u.face);
      const auto memo = tabulate_aligned_reciprocal(p, w);
      ASSERT_FALSE(memo.empty());
      const bool fits = address_fits_int32(p, memo);
      EXPECT_EQ(fits, u.fits) << "rot_frac " << u.rot_frac << ", quot_frac " << u.quot_frac << ", face " << u.face;
      const int64_t shift = int64_t{u.recip_frac} + p.n_max - 1 - u.quot_frac;
      const int64_t one = int64_t{1} << u.quot_frac, S = u.face;
      int64_t widest = 0;  // the largest magnitude any step of the 64-bit chain reached
      for (int64_t m = 1; m < static_cast<int64_t>(memo.size()); ++m) {
        std::uniform_int_distribution<int64_t> d(-m, m);
        for (const int64_t sc : {m, -m, int64_t{0}, int64_t{1}, int64_t{-1}, d(rng), d(rng)}) {
          const int64_t ya = memo[static_cast<size_t>(m)];
          const int64_t product = sc * ya;
          widest = std::max({widest, std::abs(product) + (shift > 0 ? int64_t{1} << (shift - 1) : 0)});
          const int64_t q = multiply_aligned_reciprocal(sc, ya, u.recip_frac, p.n_max, u.quot_frac, p.div_rounding);
          const int64_t qc = std::clamp(q, -one, one);
          widest = std::max(widest, (qc + one) * S + (int64_t{1} << (u.quot_frac - u.texel_frac)));
          const int64_t pos = quotient_to_position(q, p);
          if (!fits) continue;  // (the 32-bit chain would overflow: not evaluated)
          const int32_t q32 = multiply_aligned_reciprocal_as<int32_t>(static_cast<int32_t>(sc), static_cast<int32_t>(ya),
                                                                      u.recip_frac, p.n_max, u.quot_frac, p.div_rounding);
          ASSERT_EQ(q32, q) << "ma " << m << ", sc " << sc;
          ASSERT_EQ(quotient_to_position_as<int32_t>(q32, p), pos) << "ma " << m << ", sc " << sc;
        }
      }
      if (fits) EXPECT_LE(widest, INT32_MAX) << "rot_frac " << u.rot_frac << ", quot_frac " << u.quot_frac;
      else EXPECT_GT(widest, INT32_MAX) << "rot_frac " << u.rot_frac << ", quot_frac " << u.quot_frac;
    }
}

// The texel position and the face quotient against the rounding written out here from the
// definitions (not the datapath's shift helpers): position = (q + 1) S / 2^(quot_frac + 1 -
// texel_frac), rounded by texel_rounding, clamped to the face; quotient = sc y' /
// 2^(recip_frac + n_max - 1 - quot_frac) by div_rounding. Every mode, shifts right and left.
namespace {
int64_t round_by(int64_t n, int s, Rounding mode) {  // n / 2^s rounded; n may be negative; s may be <= 0
  if (s <= 0) return n * (int64_t{1} << -s);
  const int64_t d = int64_t{1} << s;
  int64_t q = n / d, r = n % d;
  if (r < 0) { --q; r += d; }  // floor
  if (mode == Rounding::Floor) return q;
  if (mode == Rounding::HalfUp) return q + (2 * r >= d ? 1 : 0);
  return q + (2 * r > d || (2 * r == d && (q & 1)) ? 1 : 0);  // half even
}
}  // namespace

TEST(CubeFaceAddressGenerator, PositionAndQuotientRoundAsTheirModesSay) {
  std::mt19937_64 rng(5);
  const struct { int quot_frac, texel_frac, face; } units[] = {{16, 8, 512}, {10, 4, 300}, {6, 9, 64}, {7, 8, 100}};
  for (const auto& u : units)
    for (Rounding div : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven})
      for (Rounding tex : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
        SCOPED_TRACE(testing::Message() << "quot_frac " << u.quot_frac << " texel_frac " << u.texel_frac << " div "
                                        << to_string(div) << " texel " << to_string(tex));
        DatapathWidths w;
        w.quot_frac = u.quot_frac;
        w.texel_frac = u.texel_frac;
        w.div_rounding = div;
        w.texel_rounding = tex;
        const AddressGeneratorParams p(w, u.face);
        const int64_t one = int64_t{1} << u.quot_frac, S = u.face;
        const int64_t max_pos = (S << u.texel_frac) - 1;
        std::vector<int64_t> quotients;  // every one within the clamp and a few beyond, or edges and a sample
        if (2 * one + 11 <= 4000) {
          for (int64_t q = -one - 5; q <= one + 5; ++q) quotients.push_back(q);
        } else {
          std::uniform_int_distribution<int64_t> qd(-one - 5, one + 5);
          for (int i = 0; i < 4000; ++i) quotients.push_back(qd(rng));
          for (int64_t e : {-one - 1, -one, -one + 1, int64_t{-1}, int64_t{0}, int64_t{1}, one - 1, one, one + 1})
            quotients.push_back(e);
        }
        for (const int64_t q : quotients) {
          const int64_t want = std::clamp(round_by((std::clamp(q, -one, one) + one) * S, u.quot_frac + 1 - u.texel_frac, tex),
                                          int64_t{0}, max_pos);
          ASSERT_EQ(quotient_to_position(q, p), want) << "q " << q;
        }
        // The quotient through generate_address: a vector whose major axis is +X (ma = x, sc = -z).
        const int64_t shift = int64_t{w.recip_frac_bits} + p.n_max - 1 - u.quot_frac;
        const auto memo = tabulate_aligned_reciprocal(p, w);
        ASSERT_FALSE(memo.empty());
        std::uniform_int_distribution<int32_t> md(1, (1 << w.rot_frac) - 1);
        for (int i = 0; i < 2000; ++i) {
          const int32_t ma = md(rng);
          std::uniform_int_distribution<int32_t> sd(-ma, ma);
          const int32_t sc = sd(rng), tc = sd(rng);
          const int64_t qs = round_by(int64_t{sc} * memo[static_cast<size_t>(ma)], static_cast<int>(shift), div);
          const int64_t qt = round_by(int64_t{tc} * memo[static_cast<size_t>(ma)], static_cast<int>(shift), div);
          const CubeAddress a = generate_address(Vec3q{ma, -tc, -sc}, p);  // +X: sc = -z, tc = -y
          ASSERT_EQ(a.face, kPosX);
          ASSERT_EQ(a.u, quotient_to_position(qs, p)) << "ma " << ma << " sc " << sc;
          ASSERT_EQ(a.v, quotient_to_position(qt, p)) << "ma " << ma << " tc " << tc;
        }
      }
}
