// arpsim gtkw: a grouped GTKWave save file for a VCD written by arpsim.
#include <cstdio>
#include <filesystem>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/AtomicFile.hpp"
#include "common/GtkwSaveFile.hpp"
#include "common/OutputPaths.hpp"

namespace arp::app {

Runner add_gtkw_command(CLI::App& app) {
  auto vcd = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("gtkw", "Write a grouped GTKWave save file for a VCD written by arpsim");
  cmd->add_option("vcd", *vcd, "The waveform (.vcd)")->required();
  cmd->add_option("--out,-o", *out, "Save file to write (default: the VCD's name with .gtkw)")->check(output_name());
  return [vcd, out] {
    const std::string target = out->empty() ? std::filesystem::path(*vcd).replace_extension(".gtkw").string() : *out;
    check_output_paths({{"--out", target}}, {{"vcd", *vcd}});
    write_text_atomic(target, gtkw_for_vcd(*vcd, std::filesystem::path(*vcd).filename().string()));
    std::printf("arpsim gtkw: %s (open: gtkwave %s %s)\n", target.c_str(), vcd->c_str(), target.c_str());
    return 0;
  };
}

}  // namespace arp::app
