// The error bounds of the default widths (docs/accuracy.md), asserted; and
// the harness's own sanity: narrower widths must measure worse.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "reference/accuracy/AccuracyHarness.hpp"

using namespace arp;

namespace {
accuracy::Options quick() {
  accuracy::Options o;
  o.frame_orientations = 2;
  o.random_orientations = 8;
  o.random_pixels = 4096;
  o.color_orientations = 1;
  return o;
}
}  // namespace

TEST(Accuracy, DefaultWidthsMeetTheirDocumentedBounds) {
  const accuracy::Report r = accuracy::run(dp::ArpConfig{}, quick());
  EXPECT_GT(r.frames.samples, 1'000'000u);
  EXPECT_LE(r.overall.max_error, 0.080) << accuracy::to_text(r);
  EXPECT_LE(r.overall.mean_error(), 0.015);
  EXPECT_GE(r.frames.exact_share(), 0.980);
  EXPECT_GE(r.random.exact_share(), 0.980);
  EXPECT_LE(r.directed.max_error, 0.050);
  EXPECT_LE(r.color.max_error, 13.0);
  EXPECT_LE(r.color.p999_error, 5.5);
  EXPECT_LE(r.color.mean_error, 0.10);
  EXPECT_LE(r.color.edge_pixels, r.color.pixels / 10000);  // face choice differs only on cube edges
  ASSERT_FALSE(r.worst.empty());
  EXPECT_DOUBLE_EQ(r.worst.front().error, r.overall.max_error);
}

TEST(Accuracy, DirectedExtremesCoverTiesZerosAndBothEndsOfTheReciprocal) {
  accuracy::Options o = quick();
  o.frame_orientations = 0;
  o.random_orientations = 0;
  o.color_orientations = 0;
  const accuracy::Report r = accuracy::run(dp::ArpConfig{}, o);
  EXPECT_GT(r.directed.samples, 2000u);
  // Ties quantise to ties, so the datapath may choose the other face of an
  // edge than the exact direction's -- but the texel it reads is adjacent.
  EXPECT_GT(r.directed.face_mismatch, 0u);
  EXPECT_LE(r.directed.max_error, 0.050);
}

TEST(Accuracy, NarrowerWidthsMeasureWorseAndTheExactDividerNoWorse) {
  accuracy::Options o = quick();
  o.frame_orientations = 1;
  o.color_orientations = 0;
  dp::ArpConfig narrow;
  narrow.widths.vec_frac = narrow.widths.mat_frac = narrow.widths.rot_frac = 10;
  const accuracy::Report def = accuracy::run(dp::ArpConfig{}, o);
  const accuracy::Report nar = accuracy::run(narrow, o);
  EXPECT_GT(nar.overall.max_error, 4 * def.overall.max_error);
  EXPECT_LT(nar.overall.exact_share(), def.overall.exact_share());
  dp::ArpConfig exact;
  exact.widths.divider = dp::DividerKind::Exact;
  const accuracy::Report ex = accuracy::run(exact, o);
  EXPECT_LE(ex.overall.max_error, def.overall.max_error + 0.01);
}

TEST(Accuracy, JsonReportCarriesEveryFigure) {
  accuracy::Options o = quick();
  o.frame_orientations = 0;
  o.random_orientations = 1;
  o.random_pixels = 100;
  o.color_orientations = 0;
  const auto j = nlohmann::json::parse(accuracy::to_json(accuracy::run(dp::ArpConfig{}, o)));
  for (const char* k : {"widths", "frames", "random", "directed", "all", "bilinear_color", "worst"}) EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["widths"]["vec_frac"], 14);
  EXPECT_EQ(j["random"]["samples"], 200);
}
