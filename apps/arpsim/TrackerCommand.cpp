// arpsim tracker: head-tracker input. `list` finds Oculus Rift DK1/DK2 trackers on USB;
// `record` streams one to a trace file; `import` converts a dataset; `synth` writes a synthetic trace.
#include <cinttypes>
#include <cstdio>
#include <set>
#include <string>

#include "Commands.hpp"
#include "common/InputError.hpp"
#include "common/Interrupt.hpp"
#include "common/OutputPaths.hpp"
#include "MotionOptions.hpp"
#include "tracker/TraceFile.hpp"
#include "tracker/DatasetImport.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceEdit.hpp"
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
  // The device's quirks, when there were any: every other counter that is not zero.
  std::string quirks;
  tracker::for_each_counter(st, [&quirks](const char* name, int64_t v) {
    static const std::set<std::string> shown{"reports", "samples", "malformed", "disconnects", "reconnects", "keep_alives"};
    if (v != 0 && !shown.count(name)) quirks += (quirks.empty() ? "" : ", ") + std::string(name) + " " + std::to_string(v);
  });
  if (!quirks.empty()) std::printf("  also: %s (gaps %.3f s in all)\n", quirks.c_str(), st.gap_s);
  return 0;
}

struct ImportArgs {
  std::string in, out, time_unit = "s", axes = "gl", columns, euler, angle_unit = "deg";
  bool scalar_last = false, drop_repeats = false;
  double resample_hz = 0;
};

int run_import(const ImportArgs& a) {
  tracker::DatasetLayout layout;
  std::string why;
  if (!tracker::parse_time_unit(a.time_unit, layout.time_unit)) throw InputError("--time-unit", a.time_unit, "must be s, ms, us or ns");
  if (!tracker::parse_angle_unit(a.angle_unit, layout.angle_unit)) throw InputError("--angle-unit", a.angle_unit, "must be deg or rad");
  if (!tracker::parse_axes(a.axes, layout.axes, why)) throw InputError("--axes", a.axes, why);
  if (a.scalar_last && !a.columns.empty()) throw InputError("--scalar-last", "", "give --columns or --scalar-last, not both");
  if (a.scalar_last) layout.columns = {"1", "2", "6", "3", "4", "5", "", "", ""};
  if (!a.columns.empty() && !tracker::parse_columns(a.columns, layout.columns, why)) throw InputError("--columns", a.columns, why);
  if (!a.euler.empty()) {
    if (!tracker::parse_euler_order(a.euler, layout.euler_order, why)) throw InputError("--euler", a.euler, why);
    if (a.columns.empty()) throw InputError("--euler", a.euler, "needs --columns naming the angle columns rx, ry, rz");
  }
  if (const std::string p = tracker::layout_problem(layout); !p.empty()) throw InputError("--columns", a.columns, p);
  if (layout.columns.rx.empty() && !a.euler.empty()) throw InputError("--euler", a.euler, "the columns hold a quaternion, not angles");
  if (a.resample_hz != 0 && !(a.resample_hz >= 1 && a.resample_hz <= 10000))
    throw InputError("--resample", std::to_string(a.resample_hz), "must be between 1 and 10000 Hz");
  check_output_paths({{"trace", a.out}}, {{"dataset", a.in}});
  std::vector<tracker::PoseSample> samples = tracker::read_head_motion_dataset(a.in, layout);
  const tracker::MotionSummary before = tracker::summarize_motion(samples);
  std::printf("arpsim tracker import: %s (%s axes, time in %s)\n", a.in.c_str(), a.axes.c_str(), a.time_unit.c_str());
  for (const auto& l : tracker::describe(before)) std::printf("  %s\n", l.c_str());
  for (const auto& w : tracker::motion_warnings(before)) std::fprintf(stderr, "arpsim tracker import: warning: %s\n", w.c_str());
  if (a.drop_repeats) {
    const size_t n = tracker::drop_repeats(samples);
    std::printf("  --drop-repeats: %zu repeated samples dropped, %zu kept\n", n, samples.size());
    if (samples.size() < 2) throw InputError(a.in, "", "fewer than two samples differ; nothing to import");
  }
  if (a.resample_hz > 0) {
    const double n = static_cast<double>(samples.back().time_ps - samples.front().time_ps) * 1e-12 * a.resample_hz;
    if (n >= tracker::kMaxResampled)
      throw InputError("--resample", std::to_string(a.resample_hz),
                       "would make " + std::to_string(static_cast<int64_t>(n)) + " samples of this " +
                           std::to_string(static_cast<double>(samples.back().time_ps - samples.front().time_ps) * 1e-12) +
                           " s dataset (at most 10 million; is the time unit right?)");
    samples = tracker::resample(samples, a.resample_hz);
    if (samples.size() < 2)
      throw InputError("--resample", std::to_string(a.resample_hz), "leaves fewer than two samples: the dataset is shorter than one period");
    std::printf("  --resample: %zu samples at %.1f Hz (spherical linear interpolation)\n", samples.size(), a.resample_hz);
  }
  if (a.drop_repeats || a.resample_hz > 0)
    for (const auto& l : tracker::describe(tracker::summarize_motion(samples))) std::printf("  now: %s\n", l.c_str());
  tracker::write_trace_csv(a.out, samples);
  std::printf("  -> %s (%zu samples, %.3f s)\n", a.out.c_str(), samples.size(),
              static_cast<double>(samples.back().time_ps - samples.front().time_ps) * 1e-12);
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
  synth->add_option("--out,-o", a->out, "Trace file to write")->required();
  auto r = std::make_shared<RecordArgs>();
  CLI::App* record = cmd->add_subcommand("record", "Stream an Oculus Rift DK1/DK2 to a trace file (CSV, docs/tracker.md)");
  record->add_option("--seconds", r->seconds, "How long to record")->capture_default_str();
  record->add_option("file", r->out, "Trace file to write")->required();
  record->add_flag("--quiet,-q", r->quiet, "No progress line");
  add_device_option(*record, r->tracker);
  auto im = std::make_shared<ImportArgs>();
  CLI::App* import = cmd->add_subcommand(
      "import", "Convert a head-motion dataset (one sample per line; columns, axes and units stated) into a trace file, "
                "with a summary of the motion and warnings for what a human head does not do (docs/tracker.md)");
  import->add_option("dataset", im->in, "Dataset file")->required();
  import->add_option("trace", im->out, "Trace file to write")->required();
  import->add_option("--time-unit", im->time_unit, "Unit of the timestamp: s, ms, us, ns")->capture_default_str();
  import->add_option("--axes", im->axes,
                     "The dataset's axes: gl (right-handed, y up, -z forward, as arpsim), unity (left-handed, +z forward), "
                     "corbillon (z up, +x forward: Corbillon et al. 2017), or where its x, y, z point in arpsim's frame, "
                     "e.g. +x,+y,-z")
      ->capture_default_str();
  import->add_option("--columns", im->columns,
                     "ROLE=COLUMN,... by number from 1 or header name; roles t, frame, qw, qx, qy, qz (quaternion) or "
                     "rx, ry, rz (angles about the dataset's x, y, z). Default t=1,frame=2,qw=3,qx=4,qy=5,qz=6");
  import->add_flag("--scalar-last", im->scalar_last, "The quaternion columns are x y z w (t=1,frame=2,qx=3,qy=4,qz=5,qw=6)");
  import->add_option("--euler", im->euler, "Euler angles: the intrinsic order, outermost first (e.g. yxz for yaw, pitch, roll in a y-up frame)");
  import->add_option("--angle-unit", im->angle_unit, "Unit of Euler angles: deg or rad")->capture_default_str();
  import->add_flag("--drop-repeats", im->drop_repeats, "Drop samples that repeat the one before (a logger faster than its tracker)");
  import->add_option("--resample", im->resample_hz, "Resample to this rate, Hz (spherical linear interpolation; for low-rate logs)");
  return [list, record, import, a, r, im] {
    if (list->parsed()) return run_list();
    if (record->parsed()) return run_record(*r);
    if (import->parsed()) return run_import(*im);
    return run_synth(*a);
  };
}

}  // namespace arp::app
