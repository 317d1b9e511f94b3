// Options every arpsim command shares: the configuration file and overrides.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::app {

struct ConfigOptions {
  std::string file;
  std::vector<std::string> sets;
  void add_to(CLI::App& cmd);
  // Embedded defaults, then the file, then --set overrides (later wins).
  dp::ArpConfig resolve() const;
};

// Writes text to path through a temporary file and a rename.
void write_text_atomic(const std::string& path, const std::string& text);

}  // namespace arp::app
