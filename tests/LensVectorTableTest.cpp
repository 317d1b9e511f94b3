#include <gtest/gtest.h>

#include <cmath>

#include "rtl_model/datapath/LensVectorTable.hpp"
#include "reference/golden/GoldenReference.hpp"

using namespace arp::dp;

namespace {
double unit(int32_t code, int frac) { return std::ldexp(static_cast<double>(code), -frac); }
}  // namespace

TEST(LensVectorTable, EveryEntryIsTheGoldenDirectionRoundedToQ1_14) {
  ArpConfig c;
  const LensVectorTable t(c.lens, c.timing, c.widths.vec_frac);
  ASSERT_EQ(t.width(), 640);
  ASSERT_EQ(t.height(), 480);
  ASSERT_EQ(t.eyes(), 2);
  const double lsb = std::ldexp(1.0, -14);
  for (int e = 0; e < 2; ++e)
    for (int y = 0; y < 480; y += 7)
      for (int x = 0; x < 640; x += 3) {
        const glm::dvec3 g = arp::golden::lens_direction(c, e, x, y);
        const Vec3q q = t.at(e, x, y);
        ASSERT_LE(std::abs(unit(q.x, 14) - g.x), 0.5 * lsb + 1e-12);
        ASSERT_LE(std::abs(unit(q.y, 14) - g.y), 0.5 * lsb + 1e-12);
        ASSERT_LE(std::abs(unit(q.z, 14) - g.z), 0.5 * lsb + 1e-12);
      }
}

TEST(LensVectorTable, GeometryOfTheDefaultLens) {
  ArpConfig c;
  const LensVectorTable t(c.lens, c.timing, 14);
  // Symmetric about the centre, looking down -z.
  const Vec3q a = t.at(0, 319, 239), b = t.at(0, 320, 240);
  EXPECT_EQ(a.x, -b.x);
  EXPECT_EQ(a.y, -b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_LT(a.z, -16380);
  // The left edge of a 90 degree lens: the first pixel centre sits at atan(1 - 1/640) from the axis.
  const Vec3q edge = t.at(0, 0, 240);
  const double angle = std::atan2(-unit(edge.x, 14), -unit(edge.z, 14));
  EXPECT_NEAR(angle, std::atan(1.0 - 1.0 / 640.0), 2e-4);
  // Up in the image is +y.
  EXPECT_GT(t.at(0, 320, 0).y, 0);
}

TEST(LensVectorTable, DistortionAndLensOffsetFollowTheModel) {
  ArpConfig c;
  c.lens.k = {1.0, 0.22, 0.24, 0.0};  // DK1-like barrel correction
  c.lens.center_offset_px = 20.0;
  c.lens.fov_deg = 100.0;
  const LensVectorTable t(c.lens, c.timing, 14);
  const double lsb = std::ldexp(1.0, -14);
  for (int e = 0; e < 2; ++e)
    for (int y : {0, 100, 479})
      for (int x : {0, 333, 639}) {
        const glm::dvec3 g = arp::golden::lens_direction(c, e, x, y);
        const Vec3q q = t.at(e, x, y);
        ASSERT_LE(std::abs(unit(q.x, 14) - g.x), 0.5 * lsb + 1e-12);
        ASSERT_LE(std::abs(unit(q.z, 14) - g.z), 0.5 * lsb + 1e-12);
      }
  // The lens centres move toward the nose: the left eye's axis is right of its panel centre.
  EXPECT_DOUBLE_EQ(LensVectorTable::lens_center_x(c.lens, c.timing, 0), 340.0);
  EXPECT_DOUBLE_EQ(LensVectorTable::lens_center_x(c.lens, c.timing, 1), 300.0);
}

TEST(LensVectorTable, WidestAnglesStayUnitAndInRange) {
  ArpConfig c;
  c.lens.fov_deg = 179.0;  // the widest lens the configuration accepts
  const LensVectorTable t(c.lens, c.timing, 14);
  for (int y : {0, 479})
    for (int x : {0, 639}) {
      const Vec3q q = t.at(0, x, y);
      const double n = std::hypot(unit(q.x, 14), unit(q.y, 14), unit(q.z, 14));
      EXPECT_NEAR(n, 1.0, 3e-4);
      EXPECT_LT(q.z, 0);  // still in front of the eye
    }
}
