// arpsim latency end to end: the comparison table, Olano et al.'s figures
// reproduced within their tolerances, the apparatus agreeing with the
// internal timestamps, the waveform and its view; bad settings refused
// before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "TestSupport.hpp"
#include "lab/LatencyStudy.hpp"

using arp::test::run_command;
using arp::test::TempDir;

namespace {
using arp::test::kArpsim;
using arp::test::load_json;
}  // namespace

TEST(LatencyCli, ComparesTheArchitecturesAndReproducesOlano) {
  TempDir d;
  const auto r = run_command(kArpsim + " latency -q --frames 40 --no-sweeps --out-dir " + d.file("lab"));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = load_json(d.file("lab/summary.json"));
  ASSERT_EQ(j["architectures"].size(), 8u);
  std::map<std::string, nlohmann::json> by;
  for (const auto& a : j["architectures"]) by[a["name"]] = a;
  // The ARP per pixel reads the orientation 556 ns ahead, plus the 1 ms tracker (and up to a 1 ms period).
  EXPECT_LT(by["arp-pixel"]["latency_ms"]["max"].get<double>(), 2.1);
  EXPECT_GT(by["conventional"]["latency_ms"]["min"].get<double>(), 50.0);
  EXPECT_LT(by["arp-pixel"]["centre_error_px"]["max"].get<double>(), by["slats"]["centre_error_px"]["max"].get<double>());
  EXPECT_LT(by["slats"]["centre_error_px"]["max"].get<double>(), by["conventional"]["centre_error_px"]["max"].get<double>());
  ASSERT_EQ(j["olano"].size(), 5u);
  for (const auto& row : j["olano"]) EXPECT_TRUE(row["within"].get<bool>()) << row.dump();
  ASSERT_EQ(j["apparatus"].size(), 8u);
  for (const auto& a : j["apparatus"]) {
    EXPECT_GE(a["passages"].get<int>(), 1) << a.dump();
    EXPECT_LE(a["max_disagreement_ms"].get<double>(), 0.002 + 1e-9) << a.dump();
  }
  for (const char* f : {"table.md", "error-over-time.csv", "latency-percentiles.csv", "apparatus.vcd", "apparatus.gtkw"})
    EXPECT_TRUE(std::filesystem::exists(d.file(std::string("lab/") + f))) << f;
  EXPECT_FALSE(std::filesystem::exists(d.file("lab/apparatus.partial.vcd")));
}

// Every file a study leaves in its --out-dir is one of lab::study_output_files(), the list the inputs are checked
// against (an input of such a name there would be written over), with the sweeps and with the apparatus.
namespace {
void expect_only_listed_lab_files(const std::string& dir) {
  const auto& listed = arp::lab::study_output_files();
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_NE(std::find(listed.begin(), listed.end(), e.path().filename().string()), listed.end()) << e.path();
  }
  EXPECT_GE(files, 8) << dir;
}
}  // namespace

TEST(LatencyCli, TheOutDirHoldsOnlyTheListedFiles) {
  TempDir d;
  const auto r = run_command(kArpsim + " latency -q --frames 4 --grid 64 --out-dir " + d.file("lab"));
  ASSERT_EQ(r.status, 0) << r.output;
  expect_only_listed_lab_files(d.file("lab"));
  // And the list guards the inputs: a trace of such a name in the folder is refused, whole afterwards.
  ASSERT_EQ(run_command(kArpsim + " tracker synth --motion rotate --seconds 5 -o " + d.file("lab/overload.csv")).status, 0);
  const auto size = std::filesystem::file_size(d.file("lab/overload.csv"));
  const auto t = run_command(kArpsim + " latency -q --frames 4 --trace " + d.file("lab/overload.csv") + " --out-dir " + d.file("lab"));
  EXPECT_EQ(t.status, 2) << t.output;
  EXPECT_NE(t.output.find("is where --out-dir puts overload.csv; it would be overwritten"), std::string::npos) << t.output;
  EXPECT_EQ(std::filesystem::file_size(d.file("lab/overload.csv")), size);
}

TEST(LatencyCli, SweepsWriteTheirTables) {
  TempDir d;
  const auto r = run_command(kArpsim + " latency -q --frames 8 --grid 64 --no-apparatus --out-dir " + d.file("lab"));
  ASSERT_EQ(r.status, 0) << r.output;
  expect_only_listed_lab_files(d.file("lab"));
  for (const char* f : {"speed-sweep.csv", "horizon-sweep.csv", "overload.csv"}) {
    std::ifstream in(d.file(std::string("lab/") + f));
    int lines = 0;
    for (std::string l; std::getline(in, l);) ++lines;
    EXPECT_GE(lines, 8) << f;
  }
}

TEST(LatencyCli, BadSettingsAreRefusedBeforeAnythingIsWritten) {
  TempDir d;
  {
    std::ofstream t(d.file("short.csv"));
    t << "time_s,qw,qx,qy,qz\n0,1,0,0,0\n0.1,1,0,0,0\n";
  }
  for (const std::string& bad : std::vector<std::string>{" --horizon-ms -5", " --slats-setup-ms 15", " --conv-copy-ms 0", " --predict maybe",
                                 " --trace " + d.file("short.csv"), " --frames 1", " --tracker-rate 0"}) {
    const auto r = run_command(kArpsim + " latency -q --no-sweeps --no-apparatus --out-dir " + d.file("out") + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("error"), std::string::npos) << bad << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(d.file("out"))) << bad;
  }
  const auto t = run_command(kArpsim + " latency -q --no-sweeps --no-apparatus --out-dir " + d.file("out") + " --trace " + d.file("short.csv"));
  EXPECT_NE(t.output.find("short.csv"), std::string::npos) << t.output;
  EXPECT_NE(t.output.find("lasts"), std::string::npos) << t.output;
  const auto h = run_command(kArpsim + " latency --help");
  EXPECT_EQ(h.status, 0);
  EXPECT_NE(h.output.find("--olano"), std::string::npos);
}
