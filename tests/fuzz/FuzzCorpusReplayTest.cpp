// The fuzz corpora replayed in the ordinary tests (and so under ASan+UBSan):
// every file in tests/fuzz/corpus/<target>/ -- the seeds from the project's
// own files and the inputs scripts/fuzz.sh found and kept -- is read or
// refused cleanly; files named valid-* are the project's own and must be
// read, not refused (a target that refuses everything fuzzes nothing).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "FuzzTargets.hpp"

namespace fs = std::filesystem;

namespace {

class FuzzCorpus : public ::testing::TestWithParam<std::string> {};

std::vector<uint8_t> bytes_of(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(f), {});
}

TEST_P(FuzzCorpus, ReplaysWithoutAFinding) {
  const auto* target = arp::fuzz::find_fuzz_target(GetParam());
  ASSERT_NE(target, nullptr);
  setenv("ARPSIM_IMPORT_HELPER", ARPSIM_IMPORT_HELPER_BINARY, 1);
  const fs::path dir = fs::path(ARPSIM_SOURCE_DIR) / "tests/fuzz/corpus" / GetParam();
  int files = 0, valid = 0, refused = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const auto b = bytes_of(e.path());
    ASSERT_LE(b.size(), target->max_len) << e.path() << " is longer than the target's -max_len";
    target->one_input(b.data(), b.size());  // a finding aborts
    ++files;
    if (GetParam() == "report") continue;  // decoder refusals are counted by its own property
    if (arp::fuzz::last_input_refused()) ++refused;
    if (e.path().filename().string().rfind("valid-", 0) == 0) {
      ++valid;
      EXPECT_FALSE(arp::fuzz::last_input_refused()) << e.path() << " is one of the project's own files and was refused";
    }
  }
  // Seeds for every target: a corpus of a handful of files is no corpus.
  EXPECT_GE(files, 5) << dir;
  if (GetParam() != "report") {
    EXPECT_GE(valid, 1) << dir << " has no valid-* seed";
    EXPECT_GE(refused, 1) << dir << " has no input the target refuses";
  }
}

std::vector<std::string> target_names() {
  std::vector<std::string> n;
  for (const auto& t : arp::fuzz::fuzz_targets()) n.push_back(t.name);
  return n;
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus, ::testing::ValuesIn(target_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
