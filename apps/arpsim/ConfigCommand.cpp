// arpsim config: prints the effective configuration (the embedded defaults
// with any file and overrides applied) as JSON, a starting point for a file;
// --list prints every key with its range, unit and doc; --update-doc rewrites
// the generated tables of docs/configuration.md from the parameter table.
#include <cstdio>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/StrictJson.hpp"
#include "sim/ConfigFile.hpp"

namespace arp::app {

Runner add_config_command(CLI::App& app) {
  struct Args {
    ConfigOptions cfg;
    bool list = false;
    std::string doc;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = a->cfg.add_command(app, "config", "Print the effective configuration as JSON (defaults embedded)");
  cmd->add_flag("--list", a->list, "Print every key with its value, range, unit and meaning instead");
  cmd->add_option("--update-doc", a->doc, "Rewrite the generated key tables of this markdown file (docs/configuration.md)")
      ->check(output_name());
  return [a] {
    const dp::ArpConfig c = a->cfg.resolve();
    if (!a->doc.empty()) {
      const std::string text = read_input_file(a->doc, 1 << 22, "markdown file");
      const std::string updated = config::update_reference_doc(text, a->doc);
      if (updated != text) write_text_atomic(a->doc, updated);
      std::printf("arpsim config: %s %s\n", a->doc.c_str(), updated == text ? "is current" : "updated");
      return 0;
    }
    std::printf("%s", a->list ? config::listing(c).c_str() : (dump_json(config::to_json(c), 2) + "\n").c_str());
    return 0;
  };
}

}  // namespace arp::app
