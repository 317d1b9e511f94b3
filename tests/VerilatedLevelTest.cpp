// The verilated level (rtl_model/verilated): frames and photon times
// identical to the functional model's, for every width configuration the RTL
// is built for; a configuration it is not built for, and a build without
// Verilator, refused with the reason. (The per-module benches are
// testbench/hdl; this is the RTL on whole frames.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/InputError.hpp"
#include "FrameFixtures.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "rtl_model/verilated/VerilatedFrameModel.hpp"

using namespace arp;
using namespace arp::dp;

namespace {

// Layered memories (the composition's tie rule in memories 1 and 2), a fast
// turn (7 degrees a millisecond: new samples every millisecond of the frame),
// a small display (test::small_display) so that a frame through the RTL takes a fraction of a second.
void expect_identical(const ArpConfig& c, const std::string& what) {
  DisplayMemorySet mem(c.memory, c.timing.eyes);
  test::fill_layered(mem);
  const FunctionalModel functional(c);
  const vl::VerilatedFrameModel rtl(c);
  const OrientationStream o = test::turning(functional.timing(), 1, 7.0);
  for (int64_t frame : {1, 2}) {
    HmdFrame want, got;
    RenderOptions ro;
    ro.photon_times = true;
    functional.render(mem, o, frame, want, ro);
    rtl.render(mem, o, frame, got, true);
    ASSERT_EQ(got.pixels.size(), want.pixels.size()) << what;
    size_t diff = 0, first = 0;
    for (size_t i = 0; i < got.pixels.size(); ++i)
      if (got.pixels[i] != want.pixels[i] && diff++ == 0) first = i;
    EXPECT_EQ(diff, 0u) << what << ", frame " << frame << ": first difference at pixel " << first;
    EXPECT_EQ(got.photon_ps, want.photon_ps) << what;
  }
  std::printf("%s: frames identical, RTL configuration '%s'\n", what.c_str(), rtl.rtl_configuration().c_str());
}

}  // namespace

TEST(VerilatedLevel, FramesAndPhotonTimesEqualTheFunctionalModelsInEveryBuiltConfiguration) {
  if (!vl::verilated_available()) GTEST_SKIP() << vl::verilated_unavailable_reason();
  ArpConfig c = test::small_display(ArpConfig{});
  expect_identical(c, "default widths, bilinear, 4 memories");
  c.pipeline.aa = AaMode::Off;
  c.pipeline.latch = LatchPolicy::PerPixel;
  expect_identical(c, "nearest texel, per-pixel latch");
  c = test::small_display(ArpConfig{});
  c.widths.vec_frac = c.widths.mat_frac = c.widths.rot_frac = 10;
  expect_identical(c, "Q1.10");
  c = test::small_display(ArpConfig{});
  c.widths.divider = DividerKind::Exact;
  expect_identical(c, "exact divider");
  c = test::small_display(ArpConfig{});
  c.widths.newton_steps = 0;
  expect_identical(c, "no Newton step");
  c = test::small_display(ArpConfig{});
  c.memory = MemoryConfig{8, 512, 5, 6, 5, 24, {0, 0, 0}};
  c.memory.background = {16, 68, 164};  // colour code 0x1234 in 5:6:5: the format565 build's background
  c.widths.texel_frac = 6;
  c.pipeline.display_bits = 6;
  expect_identical(c, "5:6:5 colour, 8 memories, 24-bit depth");
  EXPECT_EQ(vl::built_configurations().size(), 6u);
}

TEST(VerilatedLevel, AConfigurationTheRtlIsNotBuiltForIsRefusedWithTheList) {
  ArpConfig c = test::small_display(ArpConfig{});
  c.widths.vec_frac = 13;
  try {
    vl::VerilatedFrameModel m(c);
    FAIL() << "a width the RTL is not built for was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (vl::verilated_available()) {
      EXPECT_NE(what.find("orientation matrix unit"), std::string::npos) << what;
      EXPECT_NE(what.find("vec_frac/mat_frac/rot_frac/rot_rounding"), std::string::npos) << what;
      EXPECT_NE(what.find("14/14/14/1 (default)"), std::string::npos) << what;
      EXPECT_NE(what.find("13/14/14/1"), std::string::npos) << what;
    } else {
      EXPECT_NE(what.find("Verilator was not found"), std::string::npos) << what;
    }
  }
  c = test::small_display(ArpConfig{});
  c.memory.background = {0, 0, 40};
  if (vl::verilated_available()) {
    try {
      vl::VerilatedFrameModel m(c);
      FAIL() << "a background the composition unit is not built for was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("composition unit"), std::string::npos) << e.what();
    }
  }
}
