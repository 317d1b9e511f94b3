// The arpsim command line end to end: outputs appear, bad input gets a clear
// error, a non-zero exit and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "TestSupport.hpp"
#include "host/cubemap/ImageFiles.hpp"

using arp::test::run_command;
using arp::test::TempDir;

namespace {
using arp::test::kArpsim;
}

TEST(Cli, HelpOnEveryCommand) {
  for (const char* sub : {"", " frame", " verify", " config", " run", " gtkw", " tracker", " tracker list", " tracker synth"}) {
    const auto r = run_command(kArpsim + sub + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.output.find("--"), std::string::npos) << sub;
  }
  EXPECT_EQ(run_command(kArpsim).status, 2);  // a command is required
}

TEST(Cli, FrameWritesTheStereoImageAndReport) {
  TempDir d;
  const auto r = run_command(kArpsim + " frame --yaw 90 --out " + d.file("f.png") + " --report " + d.file("f.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto img = arp::host::read_rgb8(d.file("f.png"));
  EXPECT_EQ(img.width, 1280);
  EXPECT_EQ(img.height, 480);
  std::ifstream in(d.file("f.json"));
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["image"], d.file("f.png"));
  EXPECT_GT(j["last_photon_ps"].get<int64_t>(), 15'000'000'000);
  EXPECT_EQ(d.entries(), 2u);
}

// --aa is pipeline.aa before the configuration is checked: no sub-texel bits are valid without bilinear filtering
// (applied after the check, this was refused for wanting one; from a file, until the file was checked with its
// options rather than alone).
TEST(Cli, FrameAaOffAllowsNoSubTexelBits) {
  TempDir d;
  const auto r = run_command(kArpsim + " frame --set datapath.texel_frac=0 --aa off --out " + d.file("f.png"));
  EXPECT_EQ(r.status, 0) << r.output;
  const auto bilinear = run_command(kArpsim + " frame --set datapath.texel_frac=0 --aa bilinear --out " + d.file("g.png"));
  EXPECT_EQ(bilinear.status, 2) << bilinear.output;
  EXPECT_NE(bilinear.output.find("needs at least 1 sub-texel bit"), std::string::npos) << bilinear.output;
  // The same from a file: it is checked with the options that go with it, not alone.
  std::ofstream(d.file("frac0.json")) << R"({"datapath": {"texel_frac": 0}})";
  const auto file = run_command(kArpsim + " frame --config " + d.file("frac0.json") + " --aa off --out " + d.file("h.png"));
  EXPECT_EQ(file.status, 0) << file.output;
}

// The calibration pattern fills memory 0's six faces of each eye, every texel: with a pool of 10 tiles there, the
// first 10 tiles (face +X, row-major) are stored and every other texel is lost -- 6 x 512^2 - 10 x 32^2 an eye --
// counted in the report and warned about once.
TEST(Cli, AFrameWhoseTilePoolIsFullSaysSo) {
  TempDir d;
  const auto r = run_command(kArpsim + " frame --set memory.tile_pool=[10,0,0,0] --out " + d.file("f.png") + " --report " + d.file("f.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("lost for want of a tile slot"), std::string::npos) << r.output;
  std::ifstream in(d.file("f.json"));
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["texels_lost_tile_pool_full"], 2 * (6 * 512 * 512 - 10 * 32 * 32));
  EXPECT_EQ(j["texels_lost_off_tiles"], 0);
}

TEST(Cli, BadInputFailsClearlyAndLeavesNoOutput) {
  TempDir d;
  std::ofstream(d.file("bad.json")) << R"({"datapath": {"vec_frac": 40}})";
  std::ofstream(d.file("garbage.png")) << "not an image";
  const struct { std::string args, expect; } cases[] = {
      {"frame --quat 0,0,0,0", "zero"},
      {"frame --quat 1,nan,0,0", "NaN"},
      {"frame --quat 1,2", "four"},
      {"frame --yaw nan", "finite"},
      {"frame --config " + d.file("bad.json"), "datapath.vec_frac"},
      {"frame --config " + d.file("missing.json"), "cannot open"},
      {"frame --set lens.fov_deg=180", "lens.fov_deg"},
      {"frame --set display.bogus=1", "unknown key"},
      {"frame --cross " + d.file("garbage.png"), "garbage.png"},
      {"frame --equirect " + d.file("none.png"), "does not exist"},
      {"frame --faces " + d.path(), "px"},
      {"frame --aa trilinear", "--aa"},
  };
  for (const auto& c : cases) {
    const auto r = run_command(kArpsim + " " + c.args + " --out " + d.file("out.png"));
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(d.file("out.png"))) << c.args;
  }
  const auto r = run_command(kArpsim + " frame --out " + d.file("no/folder/out.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos);
  EXPECT_EQ(run_command(kArpsim + " frame --threads -1").status, 2);
  EXPECT_EQ(d.entries(), 2u);  // only the two inputs: no stray temporaries
}

TEST(Cli, VerifyPrintsTheTableAndJson) {
  TempDir d;
  const auto r = run_command(kArpsim + " verify -q --frames 0 --random 2 --pixels 200 --color-frames 0 --json " +
                             d.file("v.json") + " --set datapath.vec_frac=10");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("vectors Q1.10"), std::string::npos);
  EXPECT_NE(r.output.find("worst inputs"), std::string::npos);
  std::ifstream in(d.file("v.json"));
  EXPECT_EQ(nlohmann::json::parse(in)["widths"]["vec_frac"], 10);
}

TEST(Cli, ConfigPrintsTheEffectiveConfiguration) {
  const auto r = run_command(kArpsim + " config --set memory.count=2");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["memory"]["count"], 2);
  EXPECT_EQ(j["display"]["pixel_clock_hz"], 25175000);
}

TEST(Cli, TrackerListGivesAClearAnswer) {
  const auto r = run_command(kArpsim + " tracker list");
  // Without a headset: "no Oculus Rift DK1/DK2 found ..." (exit 0), or USB unavailable (exit 1) -- never silence.
  if (r.status == 0)
    EXPECT_TRUE(r.output.find("no Oculus Rift") != std::string::npos || r.output.find("Oculus Rift DK") != std::string::npos)
        << r.output;
  else
    EXPECT_NE(r.output.find("USB is not available"), std::string::npos) << r.output;
}

TEST(Cli, TrackerSynthWritesAReadableTraceAndRefusesBadValues) {
  TempDir d;
  const auto r = run_command(kArpsim + " tracker synth --motion pendulum --amplitude 20 --period 1.5 --seconds 0.2 --hz 500 --noise 0.1 --out " +
                             d.file("p.csv"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(d.file("p.csv"));
  std::string header, first;
  std::getline(in, header);
  std::getline(in, header);
  EXPECT_EQ(header, "time_s,qw,qx,qy,qz");
  size_t rows = 0;
  while (std::getline(in, first)) ++rows;
  EXPECT_EQ(rows, 101u);  // 0.2 s at 500 Hz, both ends
  const struct { std::string args, expect; } bad[] = {
      {"--motion shake --seconds 0", "--seconds"},
      {"--motion shake --hz -5", "--hz"},
      {"--motion shake --frequency 0", "--frequency"},
      {"--motion rotate --axis 0,0,0", "non-zero"},
      {"--motion rotate --axis 1,2", "three"},
      {"--motion rotate --noise -1", "--noise"},
      {"--motion pendulum --period nan", "--period"},
      {"--motion twirl", "twirl"},
  };
  for (const auto& b : bad) {
    const auto e = run_command(kArpsim + " tracker synth " + b.args + " --out " + d.file("bad.csv"));
    EXPECT_EQ(e.status, 2) << b.args;
    EXPECT_NE(e.output.find(b.expect), std::string::npos) << b.args << "\n" << e.output;
    EXPECT_FALSE(std::filesystem::exists(d.file("bad.csv"))) << b.args;
  }
}

TEST(Cli, RunReplaysATraceFrameByFrame) {
  TempDir d;
  ASSERT_EQ(run_command(kArpsim + " tracker synth --motion rotate --rate 300 --seconds 0.1 --out " + d.file("spin.csv")).status, 0);
  const auto r = run_command(kArpsim + " run -q --trace " + d.file("spin.csv") + " --frames 3 --out-dir " + d.file("out") +
                             " --report " + d.file("run.json") + " --set memory.face_size=128 --set display.h_active=160" +
                             " --set display.v_active=120");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto f0 = arp::host::read_rgb8(d.file("out/frame_000000.png"));
  const auto f2 = arp::host::read_rgb8(d.file("out/frame_000002.png"));
  EXPECT_EQ(f0.width, 320);
  EXPECT_NE(f0.rgb, f2.rgb);  // the head turned 10 degrees between them
  std::ifstream in(d.file("run.json"));
  const auto j = nlohmann::json::parse(in);
  ASSERT_EQ(j["frames"].size(), 3u);
  EXPECT_LT(j["frames"][0]["last_sample"].get<int>(), j["frames"][2]["last_sample"].get<int>());
  // Past the trace's end (a 64x48 frame lasts 0.83 ms: frame 1000 is at 0.83 s) the register
  // holds its last sample, and the run says so.
  const auto late = run_command(kArpsim + " run -q --trace " + d.file("spin.csv") + " --frames 1 --first-frame 1000 --every 0" +
                                " --set memory.face_size=64 --set display.h_active=64 --set display.v_active=48");
  EXPECT_EQ(late.status, 0) << late.output;
  EXPECT_NE(late.output.find("hold its last sample"), std::string::npos) << late.output;
  std::ofstream(d.file("bad.csv")) << "time_s,qw,qx,qy,qz\n0,0,0,0,0\n";
  for (const std::string& args : {"--trace " + d.file("bad.csv"), "--trace " + d.file("none.csv"),
                                  "--trace " + d.file("spin.csv") + " --frames 0",
                                  "--trace " + d.file("spin.csv") + " --every -1"}) {
    const auto e = run_command(kArpsim + " run -q " + args + " --out-dir " + d.file("never"));
    EXPECT_EQ(e.status, 2) << args << "\n" << e.output;
    EXPECT_FALSE(std::filesystem::exists(d.file("never"))) << args;
  }
}
