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
const std::string kArpsim = ARPSIM_BINARY;
}

TEST(Cli, HelpOnEveryCommand) {
  for (const char* sub : {"", " frame", " verify", " config"}) {
    const auto r = run_command(kArpsim + sub + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.output.find("--"), std::string::npos) << sub;
  }
  EXPECT_NE(run_command(kArpsim).status, 0);  // a command is required
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
  EXPECT_NE(run_command(kArpsim + " frame --threads -1").status, 0);
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
