// arpsim tracker: head-tracker input. `list` finds Oculus Rift DK1/DK2
// trackers on USB; `synth` writes a synthetic head-motion trace (CSV).
#include <cstdio>

#include "Commands.hpp"
#include "common/InputError.hpp"
#include "MotionOptions.hpp"
#include "tracker/TraceFile.hpp"
#include "tracker/UsbTrackers.hpp"

namespace arp::app {

namespace {

int run_list() {
  const tracker::UsbScan scan = tracker::scan_usb_trackers();
  if (!scan.usb_available) {
    std::printf("arpsim tracker list: USB is not available here (%s).\n", scan.usb_error.c_str());
    return 1;
  }
  if (scan.trackers.empty()) {
    std::printf("arpsim tracker list: no Oculus Rift DK1/DK2 found (vendor 0x2833, products 0x0001/0x0021); "
                "%d USB device%s visible.\n",
                scan.devices_seen, scan.devices_seen == 1 ? "" : "s");
    return 0;
  }
  for (const auto& t : scan.trackers)
    std::printf("%s  bus %03d address %03d  %s\n", t.model == tracker::RiftModel::DK1 ? "Oculus Rift DK1" : "Oculus Rift DK2",
                t.bus, t.address, t.can_open ? "ready" : t.problem.c_str());
  return 0;
}

struct SynthArgs {
  MotionOptions motion;
  std::string out;
  double seconds = 10.0, start = 0.0;
};

int run_synth(const SynthArgs& a) {
  const auto trace = a.motion.make(a.start, a.seconds);
  tracker::write_trace_csv(a.out, trace);
  std::printf("arpsim tracker synth: %zu samples (%s, %.3f s at %.1f Hz) -> %s\n", trace.size(), a.motion.motion.c_str(),
              a.seconds, a.motion.hz, a.out.c_str());
  return 0;
}

}  // namespace

Runner add_tracker_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("tracker", "Head-tracker input: find USB trackers, make synthetic traces");
  cmd->require_subcommand(1);
  CLI::App* list = cmd->add_subcommand("list", "List Oculus Rift DK1/DK2 trackers on USB");
  auto a = std::make_shared<SynthArgs>();
  CLI::App* synth = cmd->add_subcommand("synth", "Write a synthetic head-motion trace (CSV, docs/tracker.md)");
  a->motion.add_to(*synth, true);
  synth->add_option("--seconds", a->seconds, "Duration")->capture_default_str();
  synth->add_option("--start", a->start, "Time of the first sample, seconds")->capture_default_str();
  synth->add_option("--out,-o", a->out, "Trace file to write")->required();
  return [list, a] { return list->parsed() ? run_list() : run_synth(*a); };
}

}  // namespace arp::app
