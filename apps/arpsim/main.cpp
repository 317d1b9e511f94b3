// arpsim: the command line of the Address Recalculation Pipeline model.
#include <CLI/CLI.hpp>
#include <systemc>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <exception>
#include <map>

#include "Commands.hpp"
#include "CommonOptions.hpp"
#include "common/InputError.hpp"

// SystemC's library calls sc_main from sc_elab_and_sim; arpsim is its sc_main.
namespace {

// A command's printed output lost (a full disk behind `arpsim config > my.json`) is an error, not a success
// with an empty file: standard output is flushed and checked before the status is returned.
int checked_stdout(int status) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return status;
  std::fprintf(stderr, "arpsim: error: standard output: the command's output was not written whole: %s\n",
               err ? std::strerror(err) : "a write failed");
  return status == 0 ? 2 : status;
}

}  // namespace

int sc_main(int argc, char** argv) {
  CLI::App app{"arpsim - bit-accurate model of the Address Recalculation Pipeline head-mounted display"};
  app.require_subcommand(1);
  std::map<const CLI::App*, arp::app::Runner> runners;
  auto add = [&](arp::app::Runner r) { runners[app.get_subcommands({}).back()] = std::move(r); };
  add(arp::app::add_frame_command(app));
  add(arp::app::add_verify_command(app));
  add(arp::app::add_config_command(app));
  add(arp::app::add_run_command(app));
  add(arp::app::add_gtkw_command(app));
  add(arp::app::add_tracker_command(app));
  add(arp::app::add_latency_command(app));
  add(arp::app::add_live_command(app));
  add(arp::app::add_tradeoff_command(app));
  add(arp::app::add_plan_command(app));
  arp::app::strict_numbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help: the help, status 0
    // A malformed option is bad input like any other: said as every other error is, status 2.
    std::fprintf(stderr, "arpsim: error: %s\nRun with --help for more information.\n", e.what());
    return 2;
  }
  try {
    for (const auto& [sub, run] : runners)
      if (sub->parsed()) return checked_stdout(run());
  } catch (const arp::InputError& e) {
    std::fprintf(stderr, "arpsim: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arpsim: internal error: %s\n", e.what());
    return 1;
  }
  return 1;
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);  // keep stdout to arpsim's own output
  // A write past the file-size limit (`ulimit -f`) then fails with EFBIG, which every writer reports naming its
  // file and cleans up after; the signal's default action killed the run and left its temporary files behind.
  std::signal(SIGXFSZ, SIG_IGN);
  return sc_core::sc_elab_and_sim(argc, argv);
}
