// Proof that restructuring changes no output bit: a fixed set of arpsim runs
// (every fidelity level, a stall, regions with warping, the latency lab, a
// tracker trace replay) and a fingerprint of each output file, recorded in
// tests/data/bit-identity.json. Each run is one test case; its outputs must
// hash to the recorded values.
//
// Fingerprints ignore only what cannot repeat: wall-clock figures in JSON
// reports (keys listed in kVolatileKeys), the run's temporary folder in paths,
// and a VCD's date and version header. A change that alters an output on
// purpose re-records the file in a commit of its own saying what changed and
// why:  ARPSIM_RECORD_BIT_IDENTITY=1 ctest -j1 -R BitIdentity  (one at a time:
// each case rewrites the file).
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "TestSupport.hpp"

using arp::test::run_command;
using arp::test::TempDir;
using nlohmann::json;

namespace {

using arp::test::kArpsim;
const std::string kDataFile = std::string(ARPSIM_SOURCE_DIR) + "/tests/data/bit-identity.json";
const std::set<std::string> kVolatileKeys{"wall_seconds", "pixel_clocks_per_second", "host_wall_ms_per_frame", "peak_resident_mb"};

using arp::test::read_text;

json load_data() {
  std::ifstream in(kDataFile);
  return json::parse(in);
}

// 64-bit FNV-1a over bytes: a fingerprint, not a defence against tampering.
std::string fingerprint(const std::string& bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, h);
  return hex;
}

void replace_all(std::string& s, const std::string& what, const std::string& with) {
  for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + with.size())) s.replace(p, what.size(), with);
}

void drop_volatile(json& j) {
  if (j.is_object()) {
    for (const auto& k : kVolatileKeys) j.erase(k);
    for (auto& [k, v] : j.items()) drop_volatile(v);
  } else if (j.is_array()) {
    for (auto& v : j) drop_volatile(v);
  }
}

// The file's bytes as they must repeat: the run folder named OUT, wall-clock
// keys dropped from JSON, a VCD from its timescale on.
std::string normalised(const std::string& path, const std::string& out_dir) {
  std::string text = read_text(path);
  const auto ends_with = [&](const char* e) {
    const std::string ext(e);
    return path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  };
  if (ends_with(".json")) {
    json j = json::parse(text);
    drop_volatile(j);
    text = j.dump(1);
  } else if (ends_with(".vcd")) {
    const auto p = text.find("$timescale");
    if (p != std::string::npos) text = text.substr(p);
  }
  replace_all(text, out_dir, "OUT");
  return text;
}

std::vector<std::string> run_names() {
  std::vector<std::string> names;
  const json data = load_data();
  for (const auto& r : data["runs"]) names.push_back(r["name"].get<std::string>());
  return names;
}

class BitIdentity : public ::testing::TestWithParam<std::string> {};

TEST_P(BitIdentity, OutputsHashAsRecorded) {
  const json data = load_data();
  json run;
  for (const auto& r : data["runs"])
    if (r["name"] == GetParam()) run = r;
  ASSERT_FALSE(run.is_null());
  TempDir d;
  for (const auto& step : run["steps"]) {
    std::string cmd = step.get<std::string>();
    replace_all(cmd, "{out}", d.path());
    const auto r = run_command(kArpsim + " " + cmd);
    ASSERT_EQ(r.status, 0) << cmd << "\n" << r.output;
  }
  json got = json::object();
  for (const auto& [file, want] : run["outputs"].items()) {
    const std::string path = d.file(file);
    ASSERT_TRUE(std::ifstream(path).good()) << GetParam() << ": " << file << " was not written";
    got[file] = fingerprint(normalised(path, d.path()));
  }
  if (std::getenv("ARPSIM_RECORD_BIT_IDENTITY")) {
    // Record: rewrite this run's fingerprints.
    json all = load_data();
    for (auto& r : all["runs"])
      if (r["name"] == GetParam()) r["outputs"] = got;
    std::ofstream(kDataFile) << all.dump(2) << "\n";
    GTEST_SKIP() << "recorded " << GetParam();
  }
  for (const auto& [file, want] : run["outputs"].items())
    EXPECT_EQ(got[file], want) << GetParam() << ": " << file << " changed (if on purpose, re-record: see the test's header)";
}

INSTANTIATE_TEST_SUITE_P(Runs, BitIdentity, ::testing::ValuesIn(run_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
