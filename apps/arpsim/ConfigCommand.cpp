// arpsim config: prints the effective configuration (the embedded defaults
// with any file and overrides applied) as JSON, a starting point for a file.
#include <cstdio>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "apps/config/ConfigFile.hpp"

namespace arp::app {

Runner add_config_command(CLI::App& app) {
  auto args = std::make_shared<ConfigOptions>();
  CLI::App* cmd = app.add_subcommand("config", "Print the effective configuration as JSON (defaults embedded)");
  args->add_to(*cmd);
  return [args] {
    std::printf("%s\n", config::to_json(args->resolve()).dump(2).c_str());
    return 0;
  };
}

}  // namespace arp::app
