// Every parser of untrusted input as a fuzz target: any bytes must be read or
// refused with an arp::InputError whose message is short (no flood) -- never
// a crash, a hang, another exception or a runaway allocation. One table of
// targets, used by the libFuzzer binary (tests/fuzz/FuzzMain.cpp, built by
// scripts/fuzz.sh with clang) and by the corpus replay in the ordinary tests
// (tests/fuzz/FuzzCorpusReplayTest.cpp, every build, ASan included).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace arp::fuzz {

struct FuzzTarget {
  const char* name;         // the corpus folder tests/fuzz/corpus/<name>, ARPSIM_FUZZ_TARGET=<name>
  const char* what;         // the parser it drives
  size_t max_len;           // libFuzzer's -max_len for it
  // libFuzzer's per-input leak check (-detect_leaks). Off where a library
  // the target drives leaks on its own (OpenImageIO's and assimp's format
  // plugins allocate state on first use that they never free): those are not
  // arpsim's; the ASan test build still checks the replayed corpus at exit.
  bool detect_leaks;
  // arpsim runs the library behind it in the guarded helper process (model
  // import): a crash, hang or runaway allocation inside assimp is contained
  // if the guarded import refuses the same input cleanly. scripts/fuzz.sh runs
  // such a target in libFuzzer's fork mode, going on past those, and replays
  // each through the guard (ARPSIM_FUZZ_GUARDED=1): refused cleanly, it is
  // counted as contained; anything else is a finding.
  bool guarded;
  int (*one_input)(const uint8_t* data, size_t size);  // 0 always; a violated property aborts
};

const std::vector<FuzzTarget>& fuzz_targets();
// Whether the last input run on this thread was refused (an InputError):
// the replay checks that the project's own files are read, not refused.
bool last_input_refused();
const FuzzTarget* find_fuzz_target(const std::string& name);

// How the model target imports: in this process through assimp (the libFuzzer
// build, where libFuzzer's own -timeout and -rss_limit_mb watch it) or through
// the guarded helper process, as arpsim does (the replay tests; the default).
void set_model_import_in_process(bool in_process);

}  // namespace arp::fuzz
