// arpsim tracker: head-tracker input. `list` finds Oculus Rift DK1/DK2 trackers on USB;
// `record` streams one to a trace file; `synth` writes a synthetic trace; `import`
// (TrackerImportCommand.cpp) converts a dataset.
#include <cinttypes>
#include <cstdio>
#include <string>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/InputError.hpp"
#include "common/Interrupt.hpp"
#include "common/OutputPaths.hpp"
#include "MotionOptions.hpp"
#include "tracker/TraceFile.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/Recorder.hpp"
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
    std::printf("Oculus Rift %s  %s  (--device %s)\n", tracker::describe(t).c_str(), t.can_open ? "ready" : t.problem.c_str(),
                t.serial.empty() ? (std::to_string(t.bus) + ":" + std::to_string(t.address)).c_str() : t.serial.c_str());
  return 0;
}


struct RecordArgs {
  std::string out;
  tracker::TrackerChoice tracker;
  double seconds = 10.0;
  bool quiet = false;
};

// Streams the first DK1/DK2 for the given time and writes what it fused.
// An unplug mid-run is reported and survived (the device is looked for again);
// Ctrl-C stops early and still writes everything recorded.
int run_record(const RecordArgs& a) {
  if (!(a.seconds > 0) || a.seconds > 24 * 3600) throw InputError("--seconds", "", "must be more than 0 and at most a day");
  check_output_paths({{"file", a.out}}, {});
  std::string err;
  bool bad_choice = false;
  const auto source = tracker::usb_source(err, a.tracker.stream_options(), &bad_choice);
  if (!source && bad_choice) throw InputError("--device", a.tracker.device, err);  // a usage error: exit 2, as run --live usb
  if (!source) {
    std::fprintf(stderr, "arpsim tracker record: %s\n", err.c_str());
    return 1;
  }
  std::printf("arpsim tracker record: %s, %.1f s -> %s (Ctrl-C stops early and keeps what was recorded)\n",
              source->describe().c_str(), a.seconds, a.out.c_str());
  const InterruptGuard ctrl_c;  // Ctrl-C / SIGTERM end the recording early; what was recorded is written
  tracker::RecordHooks hooks;
  hooks.event = [&a](const std::string& e) { std::fprintf(stderr, "%s  %s\n", a.quiet ? "" : "\n", e.c_str()); };
  if (!a.quiet)
    hooks.progress = [&a](double el, size_t n, bool connected) {
      std::fprintf(stderr, "\r  %6.2f / %.2f s  %8zu samples  %s  ETA %.1f s   ", el, a.seconds, n,
                   connected ? "streaming" : "DISCONNECTED, retrying", a.seconds - el);
    };
  const std::vector<tracker::PoseSample> poses = tracker::record_for(*source, a.seconds, interrupt_requested, hooks);
  if (!a.quiet) std::fprintf(stderr, "\n");
  if (poses.empty()) {
    std::fprintf(stderr, "arpsim tracker record: nothing was received; %s not written\n", a.out.c_str());
    return 1;
  }
  tracker::write_trace_csv(a.out, poses);
  tracker::StreamStats st;
  source->usb_stats(st);
  std::printf("  %zu samples from %" PRId64 " reports; %" PRId64 " malformed, %" PRId64 " disconnects, %" PRId64
              " reconnects, %" PRId64 " keep-alives -> %s\n",
              poses.size(), st.reports, st.malformed, st.disconnects, st.reconnects, st.keep_alives, a.out.c_str());
  const std::string quirks = tracker::unusual_counters(st);
  if (!quirks.empty()) std::printf("  also: %s (gaps %.3f s in all)\n", quirks.c_str(), st.gap_s);
  return 0;
}

struct SynthArgs {
  tracker::MotionSpec motion;
  std::string out;
  double seconds = 10.0, start = 0.0;
};

int run_synth(const SynthArgs& a) {
  check_output_paths({{"--out", a.out}}, {});
  const auto trace = a.motion.make(a.start, a.seconds);
  tracker::write_trace_csv(a.out, trace);
  std::printf("arpsim tracker synth: %zu samples (%s, %.3f s at %.1f Hz) -> %s\n", trace.size(), a.motion.motion.c_str(),
              a.seconds, a.motion.hz, a.out.c_str());
  return 0;
}

}  // namespace

Runner add_tracker_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("tracker", "Head-tracker input: find and record USB trackers, make synthetic traces");
  cmd->require_subcommand(1);
  CLI::App* list = cmd->add_subcommand("list", "List Oculus Rift DK1/DK2 trackers on USB");
  auto a = std::make_shared<SynthArgs>();
  CLI::App* synth = cmd->add_subcommand("synth", "Write a synthetic head-motion trace (CSV, docs/tracker.md)");
  add_motion_options(*synth, a->motion, true);
  synth->add_option("--seconds", a->seconds, "Duration")->capture_default_str();
  synth->add_option("--start", a->start, "Time of the first sample, seconds")->capture_default_str();
  synth->add_option("--out,-o", a->out, "Trace file to write")->required()->check(output_name());
  auto r = std::make_shared<RecordArgs>();
  CLI::App* record = cmd->add_subcommand("record", "Stream an Oculus Rift DK1/DK2 to a trace file (CSV, docs/tracker.md)");
  record->add_option("--seconds", r->seconds, "How long to record")->capture_default_str();
  record->add_option("file", r->out, "Trace file to write")->required()->check(output_name());
  add_quiet_flag(*record, r->quiet);
  add_device_option(*record, r->tracker);
  const Subcommand import = add_tracker_import_command(*cmd);
  return [list, record, import, a, r] {
    if (list->parsed()) return run_list();
    if (record->parsed()) return run_record(*r);
    if (import.app->parsed()) return import.run();
    return run_synth(*a);
  };
}

}  // namespace arp::app
