// Helpers shared by the tests: temporary folders and running the arpsim binary.
#pragma once
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/InputError.hpp"

namespace arp::test {

#ifdef ARPSIM_BINARY
// The arpsim binary the tests run (the build's, passed by tests/CMakeLists.txt).
inline const std::string kArpsim = ARPSIM_BINARY;
#endif

// The InputError `fn` throws; one whose reason is "no error" when it throws none.
inline InputError error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e;
  }
  return InputError("", "", "no error");
}

// A fresh folder under the system temp folder, removed when the object dies.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "arpsim-test-XXXXXX").string();
    path_ = ::mkdtemp(tmpl.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  size_t entries() const {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(path_)) ++n;
    return n;
  }

 private:
  std::string path_;
};

// A file's bytes as text (empty if it cannot be read: the expectations that follow then fail).
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A JSON file, parsed (throws, failing the test, when it is not JSON).
inline nlohmann::json load_json(const std::string& path) { return nlohmann::json::parse(read_text(path)); }

struct CommandResult {
  int status = -1;
  std::string output;  // stdout and stderr together
};

inline CommandResult run_command(const std::string& cmd) {
  CommandResult r;
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// A usage a command refuses: the arguments that make it bad and part of what it must say.
struct Refusal {
  std::string args, says;
};
// Each `before + args + after` exits with status 2 (bad input) saying `says`; `not_written`, if given, does not exist after.
inline void expect_refused(const std::string& before, const std::vector<Refusal>& bad, const std::string& after = "",
                           const std::string& not_written = "") {
  for (const Refusal& b : bad) {
    const CommandResult r = run_command(before + b.args + after);
    EXPECT_EQ(r.status, 2) << b.args << "\n" << r.output;
    EXPECT_NE(r.output.find(b.says), std::string::npos) << b.args << "\n" << r.output;
    if (!not_written.empty()) {
      EXPECT_FALSE(std::filesystem::exists(not_written)) << b.args;
    }
  }
}

}  // namespace arp::test
