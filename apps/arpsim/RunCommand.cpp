// arpsim run: head motion through the pipeline at a chosen fidelity level,
// frame by frame (sim::Session). Parses the options into a sim::RunSpec,
// shows progress, prints the summary.
#include <cstdio>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "MotionOptions.hpp"
#include "common/Interrupt.hpp"
#include "sim/Session.hpp"

namespace arp::app {

namespace {

struct RunArgs {
  ConfigOptions cfg;
  sim::RunSpec spec;
  bool no_speculation = false, no_segmentation = false, quiet = false;
};

int run(RunArgs& a) {
  // (The library's photon_times also has the model fill each frame's photon times for its callers; on the
  // command line it means the files alone.)
  if (a.spec.out.photon_times && a.spec.out.every <= 0)
    throw InputError("--photon-times", "", "writes with each image --every saves, and --every 0 saves none: give --every N");
  a.spec.config = a.cfg.resolve();
  a.spec.config_source = a.cfg.source();
  a.spec.speculate = !a.no_speculation;
  a.spec.host.segmentation = !a.no_segmentation;
  const InterruptGuard ctrl_c;  // Ctrl-C / SIGTERM: stop after the frame in flight, keep what is finished
  sim::Session session(a.spec);
  for (const auto& l : session.motion_notes()) std::fprintf(stderr, "arpsim run: %s\n", l.c_str());
  ProgressLine progress(session.timed_frames().every_frame() ? "run " + scm::to_string(session.fidelity()) : "run functional/detailed", !a.quiet);
  session.on_progress = [&progress](double f, const std::string& what) { progress.update(f, what); };
  session.stop_when = interrupt_signal;
  const sim::RunSummary s = session.run();
  progress.finish();
  for (const auto& l : s.lines()) std::printf("%s\n", l.c_str());
  return s.stop_signal ? interrupted_exit_status(s.stop_signal) : 0;
}

void add_output_options(CLI::App* cmd, sim::OutputSpec& o) {
  cmd->add_option("--out-dir", o.out_dir, "Folder for frame_NNNNNN.png (created if missing)")->capture_default_str()->check(output_name("folder"));
  cmd->add_option("--every", o.every, "Write every Nth frame as an image (0: none)")->capture_default_str();
  cmd->add_flag("--photon-times", o.photon_times, "Also write photon_NNNNNN.csv (every pixel's photon time) with each image");
  cmd->add_option("--report", o.report, "JSON report: latencies, stage and FIFO statistics, underflows, speed")->check(output_name());
  cmd->add_option("--csv", o.csv, "CSV, one row per frame: underflows, latency, fingerprints")->check(output_name());
  cmd->add_option("--vcd", o.vcd, "VCD waveform (lt, cycle, detailed); a bare name goes into waveforms/; a .gtkw is written beside it")->check(output_name());
  cmd->add_option("--vcd-lines", o.vcd_lines, "Trace only scanlines START:END counted from the first frame's start");
  cmd->add_option("--vcd-time-us", o.vcd_time_us, "Trace only START:END microseconds of absolute simulated time");
  cmd->add_option("--vcd-signals", o.vcd_signals,
                  "all, or control: without each stage's register data (clocks, handshakes, FIFOs, scan position, host "
                  "port and orientation register only; a fraction of the file and of the time). cycle and detailed; "
                  "lt traces its quantum variables either way")
      ->capture_default_str();
  cmd->add_option("--error-every", o.error_every,
                  "With --walk: measure every Nth frame's error against the truth (PSNR, tracked points; 0: never)")
      ->capture_default_str();
  cmd->add_option("--truth-face-size", o.truth_face_size,
                  "With --walk: the face size of the truth the error is measured against (0: the run's own memory.face_size). "
                  "A fixed size compares runs whose faces differ: each against the same truth")
      ->capture_default_str();
  cmd->add_option("--truth-supersample", o.truth_supersample,
                  "With --walk: the truth's pixel is the mean of N x N samples over it (its pipeline at N x the display's "
                  "resolution, 1 .. 4), an area-sampled image rather than one sample at the pixel's centre")
      ->capture_default_str();
  cmd->add_option("--host-csv", o.host_csv, "With --walk: CSV, one row per display memory (rates, load); needs --report")
      ->check(output_name());
  cmd->add_option("--tear-image", o.tear_image,
                  "--regions: write a magnified view (8x) of the 48x32 window with the most crack pixels: displayed | truth | "
                  "cracks magenta, tears yellow, seams cyan")
      ->check(output_name());
  cmd->add_option("--tear-at", o.tear_at, "--tear-image: show this place instead, FRAME:EYE:X:Y (e.g. the same place in another run)");
}

void add_host_options(CLI::App* cmd, RunArgs& a) {
  sim::HostSpec& h = a.spec.host;
  add_walk_options(*cmd, h.walk, h.walk_speed, h.threshold_deg);
  cmd->add_option("--regions", h.region_size,
                  "With --walk: region priority rendering with square columns of this size, metres (0: object-level; "
                  "default: the configuration's memory.region_size_m, 0)");
  cmd->add_option("--margin", h.margin,
                  "--regions: how far into a new region before regions are re-assigned, metres (default: the configuration's "
                  "memory.region_margin_m, 0.5)");
  cmd->add_flag("--region-cubes", h.region_cubes, "--regions: cubes instead of columns, for tall worlds (objects are also cut along horizontal planes)");
  cmd->add_flag("--no-segmentation", a.no_segmentation, "--regions: do not cut large objects along region boundaries");
  cmd->add_flag("--warp", h.warp, "--regions: warp the regions' edges toward slower neighbours (hides tearing)");
  cmd->add_option("--warp-falloff", h.warp_falloff, "--warp: distance inside a region over which the warp fades, metres (0: half a region)");
  cmd->add_flag("--baseline", h.baseline, "Host baseline: everything in memory 0, rendered every frame");
  cmd->add_option("--engine-triangles", h.engine_triangles, "Simulated renderer: triangles per second (default: host.triangles_per_s)");
  cmd->add_option("--engine-fill", h.engine_fill, "Simulated renderer: texels filled per second (default: host.texels_per_s)");
  cmd->add_option("--engine-setup", h.engine_setup, "Simulated renderer: set-up per object, seconds (default: host.object_setup_s)");
}

}  // namespace

Runner add_run_command(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  sim::RunSpec& s = a->spec;
  CLI::App* cmd = a->cfg.add_command(app, "run", "Run head motion through the pipeline at a chosen fidelity level, frame by frame");
  add_memory_options(*cmd, s.memories);
  cmd->add_option("--fidelity", s.fidelity,
                  "functional (untimed), lt (loosely timed, scanline quantum), cycle (fast cycle-accurate), "
                  "detailed (detailed cycle-accurate, one SystemC module per stage; also: rtl), verilated (the "
                  "functional level's timing with the verilated RTL doing the per-pixel arithmetic; slow)")
      ->capture_default_str();
  cmd->add_option("--detail", s.detail,
                  "Switch to the detailed level for these frames, START:END (counted from the first frame, END exclusive) or "
                  "one frame, and back: functional elsewhere, identical frames; repeatable. auto: the frames where the head "
                  "turns faster than --detail-speed-dps or a --stall reaches")
      ->take_all();
  cmd->add_option("--detail-speed-dps", s.detail_speed_dps, "--detail auto: head speed over a frame above which it is detailed, deg/s")
      ->capture_default_str();
  cmd->add_option("--detail-warmup", s.detail_warmup, "--detail: detailed frames before each window (what its registers hold at the start)")
      ->capture_default_str();
  cmd->add_option("--trace", s.trace, "Trace file (CSV, docs/tracker.md); e.g. from arpsim tracker synth");
  cmd->add_option("--live", s.live,
                  "Live head motion: usb (an Oculus Rift DK1/DK2; --device chooses one), fed to the pipeline frame by frame as it arrives, "
                  "at the display's pace (functional level)");
  add_device_option(*cmd, s.tracker);
  add_record_live_option(*cmd, s.record_live);
  add_motion_options(*cmd, s.motion, false);
  cmd->add_option("--frames", s.frames, "Number of frames")->capture_default_str();
  cmd->add_option("--first-frame", s.first_frame, "Index of the first frame (sets its time)")->capture_default_str();
  add_threads_option(*cmd, s.threads);
  add_output_options(cmd, s.out);
  add_host_options(cmd, *a);
  cmd->add_option("--stall", s.stalls, "Inject a stall, STAGE:CLOCK:CYCLES (clock counted from the first frame's first pixel); repeatable")
      ->take_all();
  cmd->add_flag("--no-speculation", a->no_speculation,
                "cycle level: compute every pixel stage by stage (no frame speculation; same results, slower)");
  cmd->add_flag("--no-clock-gating{false}", s.clock_gating,
                "cycle and detailed: tick every pixel and host clock, idle ones too (same results, slower: what gating saves)");
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run(*a); };
}

}  // namespace arp::app
