// The libFuzzer binary over every fuzz target (tests/fuzz/FuzzTargets): the
// target is chosen by ARPSIM_FUZZ_TARGET (scripts/fuzz.sh sets it; "list"
// prints the targets: name, -max_len, -detect_leaks, guarded, what it drives). Built with clang only (ARPSIM_FUZZ).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "FuzzTargets.hpp"

namespace {
const arp::fuzz::FuzzTarget* target = nullptr;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* name = std::getenv("ARPSIM_FUZZ_TARGET");
  if (name && std::string(name) == "list") {
    for (const auto& t : arp::fuzz::fuzz_targets()) std::printf("%s %zu %d %d %s\n", t.name, t.max_len, t.detect_leaks ? 1 : 0, t.guarded ? 1 : 0, t.what);
    std::exit(0);
  }
  target = name ? arp::fuzz::find_fuzz_target(name) : nullptr;
  if (!target) {
    std::fprintf(stderr, "arp_fuzz: set ARPSIM_FUZZ_TARGET to one of:");
    for (const auto& t : arp::fuzz::fuzz_targets()) std::fprintf(stderr, " %s", t.name);
    std::fprintf(stderr, " (or list)\n");
    std::exit(2);
  }
  // assimp in this process, watched by libFuzzer's -timeout and -rss_limit_mb;
  // ARPSIM_FUZZ_GUARDED=1: through the guarded helper, as arpsim runs it.
  const char* guarded = std::getenv("ARPSIM_FUZZ_GUARDED");
  arp::fuzz::set_model_import_in_process(!(guarded && std::string(guarded) == "1"));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return target->one_input(data, size); }
