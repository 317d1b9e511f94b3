// Options every arpsim command shares: the configuration file and overrides.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/AtomicFile.hpp"
#include "common/OutputPaths.hpp"
#include "common/ProgressLine.hpp"
#include "sim/ConfigFile.hpp"
#include "sim/MemoryContents.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::app {

struct ConfigOptions {
  std::string file;
  std::vector<std::string> sets;
  // A subcommand of `app` that takes these options (--config, --set).
  CLI::App* add_command(CLI::App& app, std::string name, std::string description);
  // Embedded defaults, then the file, then --set overrides (later wins).
  dp::ArpConfig resolve() const { return config::resolve(file, sets); }
  // What names the configuration in messages.
  std::string source() const { return file.empty() ? "configuration" : file; }
};

// Every numeric option of `app` and its subcommands made strict: an integer
// is decimal digits with an optional sign (CLI11 alone reads "010" as octal
// and clamps 2^63 silently) inside its 64-bit range; a real number is finite
// and not an overflow ("1e400"). Applied once, after every command is added.
void strict_numbers(CLI::App& app);

// The walk through a scene and priority rendering's threshold (--walk, --speed, --threshold-deg): run and plan.
void add_walk_options(CLI::App& cmd, std::string& walk, std::optional<double>& speed, std::optional<double>& threshold_deg);

// An output's name (`what`: file or folder), given: output_name_fault's rule (an empty --report would
// silently write nothing; "-" is standard input's name), at the command line.
inline CLI::Validator output_name(const std::string& what = "file") {
  return CLI::Validator(
      [what](std::string& s) {
        const std::string fault = output_name_fault(s, what);
        return s == "-" && !fault.empty() ? "-: " + fault : fault;
      },
      "", "output name");
}

// --threads: worker threads of the functional model and the scene renderer.
void add_threads_option(CLI::App& cmd, int& threads);

// --quiet, -q: no progress line.
void add_quiet_flag(CLI::App& cmd, bool& quiet);

// The display memory contents' options (--faces, --cross, --equirect, --scene, --position, --time, --ipd).
void add_memory_options(CLI::App& cmd, sim::MemoryContents& m);

}  // namespace arp::app
