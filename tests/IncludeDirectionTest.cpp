// Dependencies point one way: datapath <- stage models <- functional/timed
// models <- sim/lab <- apps; host and tracker never include SystemC; nothing
// below apps includes apps, and no product code includes test-only code
// (testbench/, tests/). Checked on every project include of every source.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Each folder of product code and the folders it may include from (its own always).
const std::vector<std::pair<std::string, std::vector<std::string>>> kAllowed{
    {"common/", {}},
    {"rtl_model/datapath/", {"common/"}},
    {"rtl_model/stages/", {"common/", "rtl_model/datapath/"}},
    {"rtl_model/functional/", {"common/", "rtl_model/datapath/"}},
    {"rtl_model/verilated/", {"common/", "rtl_model/datapath/", "rtl_model/hdl/"}},  // hdl/: the generated model list
    {"rtl_model/systemc/", {"common/", "rtl_model/datapath/", "rtl_model/stages/", "rtl_model/functional/", "rtl_model/verilated/"}},
    {"host/", {"common/", "rtl_model/datapath/"}},
    {"tracker/", {"common/"}},
    {"reference/", {"common/", "rtl_model/datapath/", "rtl_model/functional/", "host/"}},
    {"lab/", {"common/", "rtl_model/", "host/", "tracker/"}},
    {"sim/", {"common/", "rtl_model/", "host/", "tracker/", "reference/"}},
    {"apps/", {"common/", "rtl_model/", "host/", "tracker/", "reference/", "lab/", "sim/"}},
};
// Only these may include SystemC itself.
const std::vector<std::string> kSystemC{"rtl_model/systemc/", "lab/apparatus/Oscilloscope.cpp", "apps/arpsim/main.cpp"};

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

struct Include {
  std::string file, header;
  int line;
  bool angled;
};

std::vector<Include> includes_of(const fs::path& root, const std::string& rel) {
  std::vector<Include> out;
  std::ifstream in(root / rel);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto p = line.find("#include ");
    if (p != 0) continue;
    const char open = line[9];
    const auto close = line.find(open == '<' ? '>' : '"', 10);
    if ((open != '"' && open != '<') || close == std::string::npos) continue;
    out.push_back({rel, line.substr(10, close - 10), n, open == '<'});
  }
  return out;
}

}  // namespace

TEST(IncludeDirection, EveryLayerIncludesOnlyTheLayersBelowIt) {
  const fs::path root(ARPSIM_SOURCE_DIR);
  int files = 0, checked = 0;
  for (const auto& [folder, allowed] : kAllowed) {
    for (const auto& e : fs::recursive_directory_iterator(root / folder)) {
      const std::string ext = e.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      const std::string rel = fs::relative(e.path(), root).string();
      ++files;
      for (const Include& i : includes_of(root, rel)) {
        if (i.angled) {
          if (i.header == "systemc" || starts_with(i.header, "systemc.h")) {
            bool ok = false;
            for (const auto& s : kSystemC) ok = ok || starts_with(rel, s);
            EXPECT_TRUE(ok) << rel << ":" << i.line << " includes SystemC";
          }
          continue;
        }
        if (i.header.find('/') == std::string::npos) continue;  // beside it, in its own folder
        ++checked;
        EXPECT_FALSE(starts_with(i.header, "testbench/") || starts_with(i.header, "tests/"))
            << rel << ":" << i.line << " (product code) includes test-only " << i.header;
        bool ok = starts_with(i.header, folder) || fs::exists(e.path().parent_path() / i.header);
        for (const auto& a : allowed) ok = ok || starts_with(i.header, a);
        EXPECT_TRUE(ok) << rel << ":" << i.line << " includes " << i.header << ", against the dependency direction";
      }
    }
  }
  EXPECT_GT(files, 150);
  EXPECT_GT(checked, 200);  // the scan does see the project's includes
}

// The golden reference may include only the configuration structs and the
// display memory's storage, never a datapath stage: it must stay independent
// of the arithmetic it checks.
TEST(IncludeDirection, TheGoldenReferenceIncludesNoDatapathArithmetic) {
  const fs::path root(ARPSIM_SOURCE_DIR);
  const std::vector<std::string> allowed{"rtl_model/datapath/ArpConfig.hpp", "rtl_model/datapath/DisplayMemoryBank.hpp",
                                         "rtl_model/datapath/FixedPoint.hpp"};  // FixedPoint: ArpConfig's Rounding enum
  int model_includes = 0;
  for (const auto& e : fs::directory_iterator(root / "reference/golden"))
    for (const Include& i : includes_of(root, fs::relative(e.path(), root).string()))
      if (starts_with(i.header, "rtl_model/")) {
        ++model_includes;
        EXPECT_NE(std::find(allowed.begin(), allowed.end(), i.header), allowed.end()) << i.file << " includes " << i.header;
      }
  EXPECT_GE(model_includes, 2);  // the scan does see the configuration and memory includes
}

// Apps parse arguments and print; the work is in the libraries. A command
// file that grows past 150 lines is doing a library's work.
TEST(IncludeDirection, EveryCommandFileOnlyTalks) {
  const fs::path root(ARPSIM_SOURCE_DIR);
  int commands = 0;
  for (const auto& e : fs::directory_iterator(root / "apps/arpsim")) {
    const std::string name = e.path().filename().string();
    if (name.size() < 11 || name.compare(name.size() - 11, 11, "Command.cpp") != 0) continue;
    ++commands;
    std::ifstream in(e.path());
    int lines = 0;
    for (std::string l; std::getline(in, l);) ++lines;
    EXPECT_LE(lines, 150) << "apps/arpsim/" << name << " has " << lines << " lines";
  }
  EXPECT_GE(commands, 11);  // frame, verify, config, tracker (+ import), run, gtkw, latency, live, tradeoff, plan
}
