// arpsim latency: the latency laboratory (lab::LatencyStudy): the ARP beside
// a conventional pipeline, Slats and just-in-time pixels on one head motion;
// tables, plots, sweeps, Olano et al.'s figures and the pendulum apparatus.
#include <csignal>
#include <cstdio>

#include "Commands.hpp"
#include "CommonOptions.hpp"
#include "MotionOptions.hpp"
#include "common/Interrupt.hpp"
#include "lab/LatencyStudy.hpp"

namespace arp::app {

namespace {

struct LatencyArgs {
  ConfigOptions cfg;
  lab::LatencySpec spec;
  bool quiet = false;
};

int run_latency(LatencyArgs& a) {
  a.spec.config = a.cfg.resolve();
  a.spec.config_source = a.cfg.source();
  lab::LatencyStudy study(a.spec);
  ProgressLine progress("latency", !a.quiet, study.steps());
  study.on_step = [&progress](const std::string& what) { progress.step(what); };
  const InterruptGuard ctrl_c;  // Ctrl-C / SIGTERM: stop as the step in flight finishes; every file written is whole
  study.stop_requested = interrupt_requested;
  std::string table;
  try {
    table = study.run();
  } catch (const lab::StudyStopped& e) {
    progress.finish();
    const int sig = interrupt_signal();
    std::fprintf(stderr, "arpsim latency: stopped by %s after '%s'; the files in %s are whole; table.md and summary.json were not written\n",
                 sig == SIGTERM ? "SIGTERM" : "SIGINT", e.what(), a.spec.out_dir.c_str());
    return interrupted_exit_status(sig);
  }
  std::printf("%s\n", table.c_str());
  for (const auto& n : study.notes()) std::printf("  note: %s\n", n.c_str());
  std::printf("arpsim latency: wrote %s (table.md, summary.json, error-over-time, latency%s%s)\n", a.spec.out_dir.c_str(),
              a.spec.no_sweeps ? "" : ", speed-sweep, horizon-sweep, overload", a.spec.no_apparatus ? "" : ", apparatus.vcd + .gtkw");
  return 0;
}

}  // namespace

Runner add_latency_command(CLI::App& app) {
  auto a = std::make_shared<LatencyArgs>();
  lab::LatencySpec& s = a->spec;
  CLI::App* cmd = a->cfg.add_command(
      app, "latency", "Latency laboratory: the ARP against conventional, Slats and just-in-time pixels on one head motion (docs/latency.md)");
  add_motion_options(*cmd, s.motion, false, false);  // (no --motion: a default shake these shape)
  cmd->add_option("--trace", s.trace, "Head motion from a trace file (CSV, docs/tracker.md) instead of --motion");
  cmd->add_flag("--olano", s.olano, "Olano et al.'s set-up: NTSC-like interlaced 600-pixel display, 60 deg across, 33 ms tracker");
  cmd->add_option("--frames", s.frames, "Display refreshes measured")->capture_default_str();
  cmd->add_option("--out-dir", s.out_dir, "Output folder")->capture_default_str()->check(output_name("folder"));
  cmd->add_option("--grid", s.grid, "Sample every Nth pixel and line (plus the last ones and the centre)")->capture_default_str();
  cmd->add_option("--tracker-rate", s.tracker_rate, "Tracker reports per second")->capture_default_str();
  cmd->add_option("--tracker-latency-ms", s.tracker_latency_ms, "Tracker sample -> system latency (default 1, or 33 with --olano)");
  cmd->add_option("--predict", s.predict, "Prediction: none, velocity (constant angular velocity), acceleration")->capture_default_str();
  cmd->add_option("--horizon-ms", s.horizon_ms, "Predict this far beyond the compute time (conventional, Slats, ARP)")->capture_default_str();
  cmd->add_option("--conv-transform-ms", s.conv_transform_ms, "Conventional: transform stage, stereo pair")->capture_default_str();
  cmd->add_option("--conv-render-ms", s.conv_render_ms, "Conventional: render stage set-up, stereo pair")->capture_default_str();
  cmd->add_option("--conv-copy-ms", s.conv_copy_ms, "Conventional: copy stage, stereo pair")->capture_default_str();
  cmd->add_option("--conv-triangle-rate", s.conv_rate, "Conventional: triangles rendered per second")->capture_default_str();
  cmd->add_flag("--no-field-sync", s.no_field_sync, "Conventional: stages start as soon as they can, not at vertical blanks");
  cmd->add_option("--triangles", s.triangles, "Scene size drawn per image by the conventional pipeline, Slats and just-in-time pixels")->capture_default_str();
  cmd->add_option("--walk-speed", s.walk_speed, "Also walk straight ahead at this speed, m/s (translation; 0: the head only turns)")
      ->capture_default_str();
  cmd->add_option("--theta-deg", s.theta_deg, "The ARP's priority-rendering threshold angle theta_t (0: one display-memory texel)")
      ->capture_default_str();
  cmd->add_option("--point-distance", s.point_distance, "Distance of the tracked world points, m (matters when walking)")
      ->capture_default_str();
  cmd->add_option("--scene", s.scene, "Scene whose triangles the conventional pipeline, Slats and JITP draw per image: gallery or a scene file");
  cmd->add_option("--slats-setup-ms", s.slats_setup_ms, "Slats: fixed work per field")->capture_default_str();
  cmd->add_option("--slats-copy-ms", s.slats_copy_ms, "Slats: first half of the copy, before the retrace")->capture_default_str();
  cmd->add_option("--slats-triangle-rate", s.slats_rate, "Slats: triangles per second (one GP)")->capture_default_str();
  cmd->add_option("--jitp-lead-us", s.jit_lead_us, "Just-in-time pixels: compute this long before display (-1: one line)")
      ->capture_default_str();
  cmd->add_option("--jitp-triangle-rate", s.jit_rate, "Just-in-time pixels: triangles transformed per second")->capture_default_str();
  cmd->add_flag("--no-sweeps", s.no_sweeps, "Skip the rotation-speed, horizon and overload sweeps");
  cmd->add_flag("--no-apparatus", s.no_apparatus, "Skip the simulated pendulum apparatus and its VCD");
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run_latency(*a); };
}

}  // namespace arp::app
