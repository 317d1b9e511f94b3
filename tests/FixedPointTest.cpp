#include <gtest/gtest.h>

#include <cmath>

#include "rtl_model/datapath/FixedPoint.hpp"
#include "rtl_model/datapath/ReciprocalUnit.hpp"

using namespace arp::dp;

namespace {
// v / 2^s rounded as the mode says, computed with exact long double arithmetic.
int64_t reference_round(int64_t v, int s, Rounding mode) {
  if (s <= 0) return v * (int64_t{1} << -s);
  const long double q = static_cast<long double>(v) / std::ldexp(1.0L, s);
  const long double fl = std::floor(q);
  const long double frac = q - fl;
  switch (mode) {
    case Rounding::Floor: return static_cast<int64_t>(fl);
    case Rounding::HalfUp: return static_cast<int64_t>(frac >= 0.5L ? fl + 1 : fl);
    case Rounding::HalfEven:
      if (frac > 0.5L) return static_cast<int64_t>(fl + 1);
      if (frac < 0.5L) return static_cast<int64_t>(fl);
      return static_cast<int64_t>(std::fmod(fl, 2.0L) == 0 ? fl : fl + 1);
  }
  return 0;
}
}  // namespace

TEST(FixedPoint, RoundShiftMatchesExactRoundingForEveryModeAndShift) {
  for (Rounding mode : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
    const RoundingSel sel(mode);
    for (int s = -3; s <= 6; ++s) {
      const RoundShift rs(s, mode);
      for (int64_t v = -300; v <= 300; ++v) {
        const int64_t want = reference_round(v, s, mode);
        ASSERT_EQ(rs.apply(v), want) << "v=" << v << " s=" << s << " mode=" << to_string(mode);
        ASSERT_EQ(rshift_round(v, s, sel.half_sel, sel.even), want) << "v=" << v << " s=" << s;
      }
    }
  }
}

TEST(FixedPoint, RoundShiftAtLargeMagnitudes) {
  const int64_t big = (int64_t{1} << 61) + 12345;
  for (Rounding mode : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
    EXPECT_EQ(RoundShift(30, mode).apply(big), reference_round(big, 30, mode));
    EXPECT_EQ(RoundShift(30, mode).apply(-big), reference_round(-big, 30, mode));
  }
}

TEST(FixedPoint, TiesGoWhereTheModeSays) {
  // 2.5 and -2.5 in Q.1
  EXPECT_EQ(RoundShift(1, Rounding::Floor).apply(5), 2);
  EXPECT_EQ(RoundShift(1, Rounding::HalfUp).apply(5), 3);
  EXPECT_EQ(RoundShift(1, Rounding::HalfEven).apply(5), 2);
  EXPECT_EQ(RoundShift(1, Rounding::Floor).apply(-5), -3);
  EXPECT_EQ(RoundShift(1, Rounding::HalfUp).apply(-5), -2);
  EXPECT_EQ(RoundShift(1, Rounding::HalfEven).apply(-5), -2);
  EXPECT_EQ(RoundShift(1, Rounding::HalfEven).apply(7), 4);
}

TEST(FixedPoint, SaturationToSignedWidth) {
  const SignedRange r(16);
  EXPECT_EQ(r.lo, -32768);
  EXPECT_EQ(r.hi, 32767);
  EXPECT_EQ(r.clamp(40000), 32767);
  EXPECT_EQ(r.clamp(-40000), -32768);
  EXPECT_EQ(r.clamp(123), 123);
  EXPECT_TRUE(r.contains(-32768));
  EXPECT_FALSE(r.contains(32768));
}

TEST(FixedPoint, QuantiseRealRoundsHalfEvenAndSaturates) {
  EXPECT_EQ(quantise_real(1.0, 14, 16), 16384);
  EXPECT_EQ(quantise_real(-1.0, 14, 16), -16384);
  EXPECT_EQ(quantise_real(2.0, 14, 16), 32767);     // saturates at the top of Q1.14
  EXPECT_EQ(quantise_real(-2.0, 14, 16), -32768);
  EXPECT_EQ(quantise_real(-5.0, 14, 16), -32768);
  EXPECT_EQ(quantise_real(0.5 / 16384, 14, 16), 0);  // tie to even
  EXPECT_EQ(quantise_real(1.5 / 16384, 14, 16), 2);
  EXPECT_EQ(quantise_real(-0.0, 14, 16), 0);
  EXPECT_EQ(quantise_real(1e-300, 14, 16), 0);
  EXPECT_EQ(quantise_real(1.0, 1, 3), 2);           // Q1.1 holds 1.0 exactly
  EXPECT_EQ(quantise_real(1.0, 0, 2), 1);
}

TEST(FixedPoint, RoundingNamesRoundTrip) {
  for (Rounding mode : {Rounding::Floor, Rounding::HalfUp, Rounding::HalfEven}) {
    Rounding back;
    ASSERT_TRUE(parse_rounding(to_string(mode), back));
    EXPECT_EQ(back, mode);
  }
  Rounding dummy;
  EXPECT_FALSE(parse_rounding("nearest", dummy));
}
