// The arpsim subcommands. Each registers its options on the CLI11 app and
// returns the function that runs it (exit status).
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace arp::app {

using Runner = std::function<int()>;

Runner add_frame_command(CLI::App& app);
Runner add_verify_command(CLI::App& app);
Runner add_config_command(CLI::App& app);
Runner add_tracker_command(CLI::App& app);
Runner add_run_command(CLI::App& app);
Runner add_gtkw_command(CLI::App& app);
Runner add_latency_command(CLI::App& app);
Runner add_live_command(CLI::App& app);
Runner add_tradeoff_command(CLI::App& app);
Runner add_plan_command(CLI::App& app);

// A subcommand of a command, and what runs it once it is parsed.
struct Subcommand {
  CLI::App* app;
  Runner run;
};
Subcommand add_tracker_import_command(CLI::App& tracker);

}  // namespace arp::app
