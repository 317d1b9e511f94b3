// The verilated level (rtl_model/verilated): frames and photon times
// identical to the functional model's, for every width configuration the RTL
// is built for; a configuration it is not built for, and a build without
// Verilator, refused with the reason. (The per-module benches are
// testbench/hdl; this is the RTL on whole frames.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/InputError.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "rtl_model/verilated/VerilatedFrameModel.hpp"

using namespace arp;
using namespace arp::dp;

namespace {

// The calibration pattern far away in memory 0, nearer squares in memories 1
// and 2 at one depth (the composition's tie rule), the others left empty.
void fill(DisplayMemorySet& mem) {
  const auto& fmt = mem.format();
  const int S = fmt.face_size;
  host::load_into_memories(mem, 0, host::make_calibration_pattern(S), host::far_depth(fmt));
  const uint32_t near = fmt.empty_depth() / 3;
  for (int e = 0; e < mem.eyes(); ++e)
    for (int m = 1; m < std::min(3, mem.count()); ++m) {
      auto& b = mem.bank(e, m);
      for (int f = 0; f < 6; ++f)
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x) {
            const bool in = m == 1 ? ((x * 7 / S + y * 5 / S) % 2 == 0) : ((x * 3 / S) == 1 && f != 4);
            if (in) b.write(f, x, y, fmt.pack_rgb8(m == 1 ? 250 : 30, 40 * m, 255 - 60 * f), near);
          }
      b.commit();
      b.vblank();
    }
}

// A fast turn through the frame (new samples every millisecond), and a
// small display so a frame through the RTL takes a fraction of a second.
OrientationStream fast_turn(const VideoTiming& t, int64_t frame) {
  std::vector<OrientationSample> s;
  const int64_t t0 = t.cycles_to_ps(t.frame_start_cycle(frame)) - 2'000'000'000;
  for (int i = 0; i < 24; ++i)
    s.push_back({t0 + int64_t{i} * 1'000'000'000, from_yaw_pitch_roll_deg(30.0 + 7.0 * i, 20.0 - 3.0 * i, 5.0 + 0.2 * i)});
  return OrientationStream(s, "test");
}
ArpConfig small(ArpConfig c) {
  const auto t = c.timing;
  c.timing = VideoTimingConfig::mode(t.eyes, {160, 8, 16, 16}, {120, 2, 2, 6}, 1'400'000);
  c.timing.eye_scan = t.eye_scan;
  return c;
}

void expect_identical(const ArpConfig& c, const std::string& what) {
  DisplayMemorySet mem(c.memory, c.timing.eyes);
  fill(mem);
  const FunctionalModel functional(c);
  const vl::VerilatedFrameModel rtl(c);
  const OrientationStream o = fast_turn(functional.timing(), 1);
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
  ArpConfig c = small(ArpConfig{});
  expect_identical(c, "default widths, bilinear, 4 memories");
  c.pipeline.aa = AaMode::Off;
  c.pipeline.latch = LatchPolicy::PerPixel;
  expect_identical(c, "nearest texel, per-pixel latch");
  c = small(ArpConfig{});
  c.widths.vec_frac = c.widths.mat_frac = c.widths.rot_frac = 10;
  expect_identical(c, "Q1.10");
  c = small(ArpConfig{});
  c.widths.divider = DividerKind::Exact;
  expect_identical(c, "exact divider");
  c = small(ArpConfig{});
  c.widths.newton_steps = 0;
  expect_identical(c, "no Newton step");
  c = small(ArpConfig{});
  c.memory = MemoryConfig{8, 512, 5, 6, 5, 24, {0, 0, 0}};
  c.memory.background = {16, 68, 164};  // colour code 0x1234 in 5:6:5: the format565 build's background
  c.widths.texel_frac = 6;
  c.pipeline.display_bits = 6;
  expect_identical(c, "5:6:5 colour, 8 memories, 24-bit depth");
  EXPECT_EQ(vl::built_configurations().size(), 6u);
}

TEST(VerilatedLevel, AConfigurationTheRtlIsNotBuiltForIsRefusedWithTheList) {
  ArpConfig c = small(ArpConfig{});
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
  c = small(ArpConfig{});
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
