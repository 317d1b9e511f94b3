#include "LatencyStudy.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "ArchitectureSet.hpp"
#include "LatencyLab.hpp"
#include "apparatus/Oscilloscope.hpp"
#include "common/PrintfText.hpp"
#include "common/AtomicFile.hpp"
#include "common/Gnuplot.hpp"
#include "common/GtkwSaveFile.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"
#include "common/Units.hpp"
#include "tracker/PoseSample.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/SceneFile.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceFile.hpp"
#include "common/StrictJson.hpp"

namespace arp::lab {

namespace {

namespace fs = std::filesystem;

LabConfig lab_config(const LatencySpec& a) {
  LabConfig lab;
  lab.conventional.transform_s = a.conv_transform_ms * 1e-3;
  lab.conventional.render_s = a.conv_render_ms * 1e-3;
  lab.conventional.copy_s = a.conv_copy_ms * 1e-3;
  lab.conventional.triangles_per_s = a.conv_rate;
  lab.conventional.field_sync = !a.no_field_sync;
  lab.slats.setup_s = a.slats_setup_ms * 1e-3;
  lab.slats.copy_first_half_s = a.slats_copy_ms * 1e-3;
  lab.slats.triangles_per_s = a.slats_rate;
  lab.jit_lead_s = a.jit_lead_us < 0 ? -1 : a.jit_lead_us * 1e-6;
  lab.jit_triangles_per_s = a.jit_rate;
  lab.horizon_s = a.horizon_ms * 1e-3;
  lab.triangles = a.triangles;
  lab.arp_threshold_rad = deg_to_rad(a.theta_deg);
  lab.point_distance_m = a.point_distance;
  return lab;
}

nlohmann::json to_json(const Distribution& d) {
  return {{"min", d.min}, {"p50", d.p50}, {"p99", d.p99}, {"max", d.max}, {"mean", d.mean}, {"count", d.count}};
}

// Olano et al.'s figures, from the models' own numbers on their display
// (NTSC-like, 600 px over 60 deg), whatever the run's own settings.
std::string olano_reproduction(const dp::ArpConfig& base, nlohmann::json& out) {
  dp::ArpConfig c = base;
  c.timing = ntsc_like_timing();
  c.lens.fov_deg = 60.0;
  const DisplayRaster d(c.timing, c.lens.fov_deg);
  tracker::SamplingSpec s;
  s.rate_hz = 20000;
  s.duration_s = 2.0;
  const auto yaw200 = tracker::constant_rotation({0, 1, 0}, 200.0, s);
  const TrackerFeed ideal(yaw200, TrackerModel{1e6, 0.0}, "olano");
  const TrackerFeed optical(yaw200, TrackerModel{1e6, 0.033}, "olano");  // the optical ceiling tracker: 33 ms
  const double field_ms = static_cast<double>(d.field_period_ps()) * 1e-9;
  LabSettings ls;
  ls.first_frame = 40;
  ls.frames = 20;
  // 1. Error per field of latency at 200 deg/s (Slats: one field).
  SlatsPipeline slats(d, SlatsConfig{}, "olano");
  const auto rs = measure(slats, d, ideal, ls);
  double per_field = 0;
  for (const auto& f : rs.frames) per_field += f.centre_error_px / (f.centre_latency_ms / field_ms);
  per_field /= static_cast<double>(rs.frames.size());
  // 2. Just-in-time pixels, one transform per scanline, predicted to the line's start.
  JustInTimePixels line(d, JitConfig{JitMode::PerScanline, -1, 0, 2e6}, "olano");
  LabSettings fine = ls;
  fine.frames = 2;
  fine.grid_step = 1;
  fine.prediction = Prediction::Velocity;
  const double jit_line = measure(line, d, ideal, fine).max_error.max;
  const double per_line_period = 200.0 * static_cast<double>(d.line_period_ps()) * 1e-12 * d.pixels_per_degree();
  // 3. Latency to the start of scan-out with the 33 ms tracker.
  ConventionalPipeline pphigs(d, ConventionalConfig{}, "olano");
  const double conv_ms = measure(pphigs, d, optical, ls).latency.min;
  const double slats_ms = measure(slats, d, optical, ls).latency.min;
  struct Row {
    const char* what;
    double model, paper, tolerance;  // relative
    const char* note;
  };
  const Row rows[] = {
      {"error per field of latency at 200 deg/s (px)", per_field, 33.0, 0.02, "Slats, screen centre, ideal tracker; 200/59.94 x 10 px/deg = 33.4"},
      {"JITP per scanline: worst error within a line (px)", jit_line, 0.13, 0.30,
       "predicted to each line's start; the paper's 0.13 is a whole 65 us line, the active part here is 48.9 us"},
      {"JITP per scanline: rotation over one line period (px)", per_line_period, 0.13, 0.03, "200 deg/s x 63.6 us x 10 px/deg"},
      {"PPHIGS + tracker: latency to the start of scan-out (ms)", conv_ms, 90.0, 0.10,
       "model: 3 fields (figure 7's minimum) + 33 ms; Olano et al. measured 54-57 ms for PPHIGS, 4-7 ms over the minimum"},
      {"Slats + tracker: latency to the start of scan-out (ms)", slats_ms, 50.0, 0.02, "one field + 33 ms"},
  };
  std::string md = "\n## Olano et al.'s figures, from the models (their display: NTSC-like, 600 px over 60 deg, 59.94 fields/s)\n\n"
                   "| figure | model | paper | tolerance | within | how |\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& r : rows) {
    const bool ok = std::abs(r.model - r.paper) <= r.tolerance * r.paper;
    md += std::string("| ") + r.what + " | " + printf_text("%.3f", r.model) + " | " + printf_text("%.2f", r.paper) + " | " + printf_text("%.0f %%", r.tolerance * 100) +
          " | " + (ok ? "yes" : "**no**") + " | " + r.note + " |\n";
    out.push_back({{"figure", r.what}, {"model", r.model}, {"paper", r.paper}, {"tolerance", r.tolerance}, {"within", ok}});
  }
  md += "\nThe 90 ms against 50 ms comparison is figure 9's; " + printf_text("%.1f", field_ms) + " ms is one field.\n";
  return md;
}

}  // namespace

const std::vector<std::string>& study_output_files() {
  static const std::vector<std::string> files = [] {
    std::vector<std::string> f = {"table.md",        "summary.json",        "error-over-time.csv", "latency-percentiles.csv",
                                  "speed-sweep.csv", "horizon-sweep.csv",   "overload.csv",        "apparatus.vcd",
                                  "apparatus.gtkw",  "apparatus.partial"};
    for (const char* plot : {"error-over-time", "latency", "speed-sweep", "horizon-sweep", "overload"})
      for (const char* ext : {".gp", ".gp.log", ".png"}) f.push_back(std::string(plot) + ext);
    return f;
  }();
  return files;
}

namespace {

// What the pipelines' own checks name: the options that set them.
const char* const kSettings = "the pipelines' settings (--conv-*, --slats-*, --jitp-*, --triangles, --scene)";

// The laboratory's display: the configuration's, or Olano's NTSC-like one (--olano).
dp::ArpConfig study_config(const LatencySpec& a) {
  dp::ArpConfig c = a.config;
  if (a.olano) {
    c.timing = ntsc_like_timing();
    c.lens.fov_deg = 60.0;
  }
  return c;
}

}  // namespace

// Every setting checked here, naming its option, so that neither steps() nor run() meets a bad one (steps()
// builds the architectures, whose own checks name no option).
LatencyStudy::LatencyStudy(LatencySpec spec) : s_(std::move(spec)) {
  const LatencySpec& a = s_;
  const dp::ArpConfig c = study_config(a);
  const auto issues = dp::validate(c);
  if (!issues.empty()) throw InputError(a.config_source, issues.front().key, issues.front().reason);
  if (a.frames < 2 || a.frames > 100000) throw InputError("--frames", "", "must be 2 .. 100000");
  if (a.grid < 1 || a.grid > 512) throw InputError("--grid", "", "must be 1 .. 512 pixels");
  if (!(a.horizon_ms >= 0)) throw InputError("--horizon-ms", "", "must be >= 0 (prediction looks ahead, not back)");
  if (a.horizon_ms > 1000) throw InputError("--horizon-ms", "", "must be at most 1000 ms");
  if (!a.trace.empty() && a.motion.given()) throw InputError("--trace", "", "give either --trace or --motion, not both");
  check_out_dir_files("--out-dir", a.out_dir,
                      {{"--trace", a.trace}, {"--scene", a.scene == "gallery" ? "" : a.scene}, {"--config", a.config_source}},
                      [](const std::string& name) {
                        const auto& f = study_output_files();
                        return std::find(f.begin(), f.end(), name) != f.end() ? name : std::string();
                      });
  for (auto [name, v] : {std::pair<const char*, double>{"--conv-transform-ms", a.conv_transform_ms}, {"--conv-render-ms", a.conv_render_ms},
                         {"--conv-copy-ms", a.conv_copy_ms}, {"--conv-triangle-rate", a.conv_rate}, {"--slats-setup-ms", a.slats_setup_ms},
                         {"--slats-copy-ms", a.slats_copy_ms}, {"--slats-triangle-rate", a.slats_rate},
                         {"--jitp-triangle-rate", a.jit_rate}})
    if (!(v > 0) || !std::isfinite(v)) throw InputError(name, "", "must be a positive number");
  if (!(a.triangles >= 0) || !std::isfinite(a.triangles)) throw InputError("--triangles", "", "must be >= 0");
  if (!(a.walk_speed >= 0) || a.walk_speed > 50) throw InputError("--walk-speed", "", "must be 0 .. 50 m/s");
  if (!(a.theta_deg >= 0) || a.theta_deg > 90) throw InputError("--theta-deg", "", "must be 0 (one texel) .. 90 degrees");
  if (!(a.point_distance > 0) || a.point_distance > 1e4) throw InputError("--point-distance", "", "must be more than 0 and at most 10 km");
  if (a.tracker_latency_ms && !(*a.tracker_latency_ms >= 0 && *a.tracker_latency_ms <= 1000))
    throw InputError("--tracker-latency-ms", "", "must be 0 .. 1000 ms");
  if (a.jit_lead_us != -1 && !(a.jit_lead_us >= 0 && a.jit_lead_us <= 1e6))
    throw InputError("--jitp-lead-us", "", "must be 0 .. 1000000 us (or -1: one line)");
  if (a.tracker_rate < 1 || a.tracker_rate > tracker::kMaxSampleRateHz)
    throw InputError("--tracker-rate", "", "must be 1 .. 1000000 reports a second");
  Prediction pred;
  if (!parse_prediction(a.predict, pred)) throw InputError("--predict", a.predict, "must be none, velocity or acceleration");
  if (!a.scene.empty()) {
    // A real scene's size drives the renderers that draw it per image.
    if (a.triangles != 0) throw InputError("--triangles", "", "give either --triangles or --scene, not both");
    const host::Scene sc = a.scene == "gallery" ? host::make_gallery() : host::load_scene_file(a.scene);
    scene_triangles_ = static_cast<double>(sc.triangles());
    scene_note_ = "; scene " + a.scene + " (" + std::to_string(sc.triangles()) + " triangles per image)";
  }
  // The pipelines' own checks (a render stage over 10 s, Slats' set-up beyond a field), before the progress line's count.
  make_architectures(DisplayRaster(c.timing, c.lens.fov_deg), c, lab(), kSettings);
}

LabConfig LatencyStudy::lab() const {
  LabConfig l = lab_config(s_);
  if (scene_triangles_ >= 0) l.triangles = scene_triangles_;
  return l;
}

int64_t LatencyStudy::steps() const {
  const dp::ArpConfig c = study_config(s_);
  const int64_t archs = static_cast<int64_t>(make_architectures(DisplayRaster(c.timing, c.lens.fov_deg), c, lab(),
                                                                kSettings).size());
  return archs + (s_.no_sweeps ? 0 : 8 + 21 + 7) + (s_.no_apparatus ? 0 : 1) + 1;
}

std::string LatencyStudy::run() {
  const LatencySpec& a = s_;
  auto step = [this](const std::string& what) {
    if (stop_requested && stop_requested()) throw StudyStopped(what);
    if (on_step) on_step(what);
  };
  auto note = [this](const std::string& n) {
    if (!n.empty()) notes_.push_back(n);
  };
  const dp::ArpConfig c = study_config(a);
  Prediction pred{};
  parse_prediction(a.predict, pred);  // (checked by the constructor)
  TrackerModel tm;
  tm.rate_hz = a.tracker_rate;
  tm.latency_s = a.tracker_latency_ms.value_or(a.olano ? 33.0 : 1.0) * 1e-3;
  LabConfig lab = this->lab();
  const std::string& scene_note = scene_note_;
  const DisplayRaster d(c.timing, c.lens.fov_deg);
  const fs::path out(a.out_dir);

  // The head motion: a trace, or synthetic (a 200 deg/s-peak head shake by default).
  const double frame_s = static_cast<double>(d.timing().cycles_to_ps(d.timing().frame_cycles())) * 1e-12;
  const double span_s = static_cast<double>(a.frames) * frame_s;
  // Every architecture needs motion from before its first image (a conventional
  // frame starts several fields early; the tracker lags).
  const double before_s = 0.3 + tm.latency_s;
  const int64_t first_frame = static_cast<int64_t>(std::ceil(before_s / frame_s)) + 1;
  const double t_first = static_cast<double>(d.photon_ps(first_frame, 0, 0)) * 1e-12;
  std::vector<tracker::PoseSample> motion;
  std::string motion_name;
  if (!a.trace.empty()) {
    motion = tracker::read_trace_csv(a.trace);
    motion_name = a.trace;
    if (motion.size() < 2) throw InputError(a.trace, "", "the trace needs at least two samples");
    const tracker::MotionSummary ms = tracker::summarize_motion(motion);
    note("trace " + a.trace + ": " + tracker::describe(ms)[0]);
    for (const auto& w : tracker::motion_warnings(ms)) note("warning: " + w);
    // Played from its first sample at time zero.
    const int64_t t0 = motion.front().time_ps;
    // Only what is played, and a sample after it: a trace may span +-9e6 s, more picoseconds from its first
    // sample than int64_t holds (offsets are compared in double before any is subtracted).
    auto offset_s = [&](const tracker::PoseSample& s) { return (static_cast<double>(s.time_ps) - static_cast<double>(t0)) * 1e-12; };
    const double have = offset_s(motion.back());
    size_t keep = 1;
    while (keep < motion.size() && offset_s(motion[keep]) <= t_first + span_s) ++keep;
    if (keep < motion.size()) {
      if (offset_s(motion[keep]) >= 9e6)
        throw InputError(a.trace, "", "after its sample at " + printf_text("%.3f", offset_s(motion[keep - 1])) +
                                          " s from its first, the next is " + printf_text("%.6g", offset_s(motion[keep])) +
                                          " s from it: more than the laboratory's picosecond clock holds");
      ++keep;
    }
    motion.resize(keep);
    for (auto& s : motion) s.time_ps -= t0;
    if (have < t_first + span_s)
      throw InputError(a.trace, "", "the trace lasts " + printf_text("%.3f", have) + " s; the laboratory needs " + printf_text("%.3f", t_first + span_s) +
                                        " s (the pipelines' latency plus --frames)");
  } else {
    tracker::MotionSpec m = a.motion;
    if (!m.given()) m.motion = "shake";
    motion = m.make(0.0, t_first + span_s + 0.1);
    motion_name = m.motion == "rotate" ? "rotate at " + printf_text("%.0f", m.rate) + " deg/s"
                  : m.motion == "shake" ? "head shake, " + printf_text("%.0f", m.peak) + " deg/s peak at " + printf_text("%.2f", m.frequency) + " Hz"
                                        : "pendulum " + printf_text("%.0f", m.amplitude) + " deg, " + printf_text("%.2f", m.period) + " s";
  }
  if (a.walk_speed > 0) {
    // Walking straight ahead (world -z) at eye height while the head turns: translation for every architecture.
    for (auto& p : motion) {
      p.has_position = true;
      p.position = glm::dvec3(0, 1.6, -a.walk_speed * static_cast<double>(p.time_ps) * 1e-12);
    }
    motion_name += ", walking " + printf_text("%.2f", a.walk_speed) + " m/s";
  }
  const TrackerFeed feed(motion, tm, a.trace.empty() ? "--motion" : a.trace);
  auto archs = make_architectures(d, c, lab, kSettings, &feed);
  std::vector<std::string> names;
  for (const auto& ar : archs) names.push_back(ar->name());
  make_output_folder("--out-dir", out);  // only once every setting has been checked

  LabSettings ls;
  ls.first_frame = first_frame;
  ls.frames = a.frames;
  ls.grid_step = a.grid;
  ls.prediction = pred;
  ls.point_distance_m = a.point_distance;
  std::vector<ArchitectureResult> results;
  for (auto& ar : archs) {
    results.push_back(measure(*ar, d, feed, ls));
    step(ar->name());
  }

  // The comparison table and its JSON.
  nlohmann::json summary{{"display",
                          {{"width", d.width()}, {"height", d.height()}, {"fields_per_frame", d.fields_per_frame()},
                           {"field_rate_hz", 1e12 / static_cast<double>(d.field_period_ps())}, {"fov_deg", d.fov_deg()},
                           {"pixels_per_degree", d.pixels_per_degree()}}},
                         {"motion", motion_name},
                         {"tracker", {{"rate_hz", tm.rate_hz}, {"latency_ms", tm.latency_s * 1e3}}},
                         {"prediction", {{"mode", to_string(pred)}, {"horizon_ms", a.horizon_ms}}},
                         {"frames", a.frames},
                         {"first_frame", first_frame},
                         {"grid_step", a.grid}};
  std::string md = "# Latency laboratory\n\nDisplay " + std::to_string(d.width()) + "x" + std::to_string(d.height()) +
                   (d.fields_per_frame() == 2 ? " interlaced" : "") + ", " + printf_text("%.2f", 1e12 / static_cast<double>(d.field_period_ps())) +
                   " fields/s, " + printf_text("%.0f", d.fov_deg()) + " deg across (" + printf_text("%.2f", d.pixels_per_degree()) + " px/deg); motion: " +
                   motion_name + "; tracker " + printf_text("%.0f", tm.rate_hz) + " Hz, " + printf_text("%.1f", tm.latency_s * 1e3) + " ms latency; prediction " +
                   to_string(pred) + " (horizon " + printf_text("%.1f", a.horizon_ms) + " ms)" + scene_note +
                   (feed.has_positions() ? "; tracked points " + printf_text("%.1f", a.point_distance) + " m away" : std::string()) + "; " + std::to_string(a.frames) + " refreshes, every " +
                   std::to_string(a.grid) + "th pixel and line.\n\n"
                   "Latency: photon time minus the sample time of the tracker report the pixel was computed from. "
                   "Error: the angle between where the pixel's pose put a world point and where the true head at the pixel's photon "
                   "time sees it, in display pixels (angle x px/deg).\n\n"
                   "| architecture | new image every (ms) | latency min / median / p99 / max (ms) | centre error mean / max (px) | worst error (px) | images missed |\n"
                   "| --- | --- | --- | --- | --- | --- |\n";
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    summary["architectures"].push_back({{"name", r.name},
                                        {"description", r.description},
                                        {"image_interval_ms", r.image_interval_s * 1e3},
                                        {"latency_ms", to_json(r.latency)},
                                        {"centre_error_px", to_json(r.centre_error)},
                                        {"frame_max_error_px", to_json(r.max_error)},
                                        {"missed_images", r.missed_images},
                                        {"position_age_ms", to_json(r.position_age_ms)},
                                        {"refreshes_without_image", r.frames_without_image}});
    md += "| " + r.name + " | " + printf_text("%.1f", r.image_interval_s * 1e3) + " | " +
          (r.latency.count ? printf_text("%.3f", r.latency.min) + " / " + printf_text("%.3f", r.latency.p50) + " / " + printf_text("%.3f", r.latency.p99) + " / " +
                                 printf_text("%.3f", r.latency.max)
                           : std::string("no image")) +
          " | " + (r.latency.count ? printf_text("%.2f", r.centre_error.mean) + " / " + printf_text("%.2f", r.centre_error.max) + " | " + printf_text("%.2f", r.max_error.max)
                                   : std::string("- | -")) +
          " | " + std::to_string(r.missed_images) + " |\n";
  }
  if (feed.has_positions()) {
    md += "\nThe head also moves: the position each image was drawn from is older than its orientation for the ARP "
          "(priority rendering re-renders the memory on need and shows it a frame later):\n\n"
          "| architecture | position age at the photon, median / max (ms) |\n| --- | --- |\n";
    for (const auto& r : results)
      if (r.position_age_ms.count)
        md += "| " + r.name + " | " + printf_text("%.2f", r.position_age_ms.p50) + " / " + printf_text("%.2f", r.position_age_ms.max) + " |\n";
  }
  md += "\nArchitectures:\n\n";
  for (const auto& r : results) md += "- **" + r.name + "**: " + r.description + "\n";

  // Error over time at the screen centre (figure 9) and the latency distributions.
  {
    std::string csv = "time_s";
    for (const auto& n : names) csv += "," + n;
    csv += "\n";
    for (size_t f = 0; f < static_cast<size_t>(a.frames); ++f) {
      csv += printf_text("%.6f", results[0].frames[f].time_s);
      for (const auto& r : results) csv += r.frames[f].shown ? "," + printf_text("%.4f", r.frames[f].centre_error_px) : ",";
      csv += "\n";
    }
    write_text_atomic((out / "error-over-time.csv").string(), csv);
    std::string lat = "percentile";
    for (const auto& n : names) lat += "," + n;
    lat += "\n";
    std::vector<std::vector<double>> sorted;
    for (const auto& r : results) {
      sorted.push_back(r.latency_ms);
      std::sort(sorted.back().begin(), sorted.back().end());
    }
    for (int p = 0; p <= 100; ++p) {
      lat += std::to_string(p);
      for (const auto& v : sorted)
        lat += v.empty() ? "," : "," + printf_text("%.6f", v[std::min(v.size() - 1, static_cast<size_t>(std::llround(p / 100.0 * static_cast<double>(v.size() - 1))))]);
      lat += "\n";
    }
    write_text_atomic((out / "latency-percentiles.csv").string(), lat);
    note(run_gnuplot(out / "error-over-time.gp",
         "set terminal pngcairo size 1100,500 font ',10'\nset output 'error-over-time.png'\nset datafile separator ','\n"
         "set title 'Registration error at the screen centre (after Olano et al., figure 9): " + motion_name + "'\n"
         "set xlabel 'time (s)'\nset ylabel 'error (pixels)'\nset grid\nset key outside right\nset logscale y\nset yrange [1e-3:*]\n"
         "plot " + plot_columns("error-over-time.csv", 2, names) + "\n"));
    note(run_gnuplot(out / "latency.gp",
         "set terminal pngcairo size 1100,500 font ',10'\nset output 'latency.png'\nset datafile separator ','\n"
         "set title 'Motion-to-photon latency of every sampled pixel (distribution)'\nset xlabel 'latency (ms)'\n"
         "set ylabel 'share of pixels (percentile)'\nset logscale x\nset grid\nset key outside right\n"
         "plot " + [&] {
           std::string s;
           for (size_t i = 0; i < names.size(); ++i)
             s += (i ? ", " : "") + std::string("'latency-percentiles.csv' using ") + std::to_string(i + 2) + ":1 with lines lw 2 title '" + names[i] + "'";
           return s;
         }() + "\n"));
  }

  if (!a.no_sweeps) {
    LabSettings sw = ls;
    sw.grid_step = std::max(a.grid, 32);
    sw.frames = std::min<int64_t>(a.frames, 60);
    // Worst error against rotation speed (constant yaw).
    std::string csv = "deg_per_s";
    for (const auto& n : names) csv += "," + n;
    csv += "\n";
    for (double sp : {0.0, 50.0, 100.0, 200.0, 300.0, 370.0, 500.0, 1000.0}) {
      tracker::SamplingSpec s;
      s.rate_hz = 2000;
      s.duration_s = t_first + span_s + 0.1;
      const TrackerFeed f(tracker::constant_rotation({0, 1, 0}, sp, s), tm, "speed sweep");
      csv += printf_text("%.0f", sp);
      for (auto& ar : archs) {
        const auto r = measure(*ar, d, f, sw);
        csv += r.latency.count ? "," + printf_text("%.4f", r.max_error.max) : ",";
      }
      csv += "\n";
      step("rotation speed " + printf_text("%.0f", sp) + " deg/s");
    }
    write_text_atomic((out / "speed-sweep.csv").string(), csv);
    note(run_gnuplot(out / "speed-sweep.gp",
         "set terminal pngcairo size 1100,500 font ',10'\nset output 'speed-sweep.png'\nset datafile separator ','\n"
         "set title 'Worst registration error against head rotation speed'\nset xlabel 'yaw rate (deg/s)'\nset ylabel 'worst error (pixels)'\n"
         "set logscale y\nset grid\nset key outside right\nplot " + plot_columns("speed-sweep.csv", 2, names, "linespoints") + "\n"));
    // Mean centre error against the prediction horizon (the main motion, constant-velocity prediction).
    csv = "horizon_ms";
    for (const auto& n : names) csv += "," + n;
    csv += "\n";
    LabSettings hp = sw;
    hp.prediction = pred == Prediction::None ? Prediction::Velocity : pred;
    for (int h = 0; h <= 100; h += 5) {
      LabConfig hl = lab;
      hl.horizon_s = h * 1e-3;
      auto ha = make_architectures(d, c, hl, "horizon sweep", &feed);
      csv += std::to_string(h);
      for (auto& ar : ha) {
        const auto r = measure(*ar, d, feed, hp);
        csv += r.latency.count ? "," + printf_text("%.4f", r.centre_error.mean) : ",";
      }
      csv += "\n";
      step("prediction horizon " + std::to_string(h) + " ms");
    }
    write_text_atomic((out / "horizon-sweep.csv").string(), csv);
    note(run_gnuplot(out / "horizon-sweep.gp",
         "set terminal pngcairo size 1100,500 font ',10'\nset output 'horizon-sweep.png'\nset datafile separator ','\n"
         "set title 'Mean centre error against the prediction horizon (" + std::string(to_string(hp.prediction)) + " prediction; JITP predicts to each display time)'\n"
         "set xlabel 'horizon beyond the compute time (ms)'\nset ylabel 'mean error (pixels)'\nset logscale y\nset grid\nset key outside right\n"
         "plot " + plot_columns("horizon-sweep.csv", 2, names, "linespoints") + "\n"));
    // Renderer overload: the scene grows; the ARP's rotation does not care.
    csv = "triangles";
    for (const auto& n : names) csv += "," + n;
    csv += ",conventional_image_interval_ms,conventional_latency_p50_ms\n";
    tracker::SamplingSpec s;
    s.rate_hz = 2000;
    s.duration_s = t_first + span_s + 0.1;
    const TrackerFeed f200(tracker::constant_rotation({0, 1, 0}, 200.0, s), tm, "overload");
    for (double tri : {0.0, 50.0, 200.0, 5000.0, 20000.0, 50000.0, 100000.0}) {
      LabConfig ol = lab;
      ol.triangles = tri;
      auto oa = make_architectures(d, c, ol, "overload sweep");
      csv += printf_text("%.0f", tri);
      double interval = 0, lat50 = 0;
      for (auto& ar : oa) {
        const auto r = measure(*ar, d, f200, sw);
        csv += r.latency.count ? "," + printf_text("%.4f", r.max_error.max) : ",";
        if (ar->name() == "conventional") {
          interval = r.image_interval_s * 1e3;
          lat50 = r.latency.p50;
        }
      }
      csv += "," + printf_text("%.3f", interval) + "," + printf_text("%.3f", lat50) + "\n";
      step("scene of " + printf_text("%.0f", tri) + " triangles");
    }
    write_text_atomic((out / "overload.csv").string(), csv);
    note(run_gnuplot(out / "overload.gp",
         "set terminal pngcairo size 1100,500 font ',10'\nset output 'overload.png'\nset datafile separator ','\n"
         "set title 'Renderer overload at 200 deg/s: worst error against scene size (Slats and JITP draw nothing past their budgets)'\n"
         "set xlabel 'triangles in the scene'\nset ylabel 'worst error (pixels)'\nset logscale xy\nset xrange [10:*]\nset grid\nset key outside right\n"
         "plot " + plot_columns("overload.csv", 2, names, "linespoints") + "\n"));
  }

  // The pendulum apparatus on the same architectures (tracker, prediction and display as above).
  if (!a.no_apparatus) {
    apparatus::PendulumSpec ps;
    const double run_s = std::max(3.0, span_s);
    const int64_t pfirst = first_frame;
    const int64_t pframes = static_cast<int64_t>(std::ceil(run_s / frame_s));
    const double t_end = static_cast<double>(d.photon_ps(pfirst + pframes, 0, 0)) * 1e-12;
    const TrackerFeed pf(apparatus::pendulum_motion(ps, t_end + 0.2, 2000), tm, "pendulum");
    std::vector<apparatus::ChannelEvents> ch;
    for (auto& ar : archs) ch.push_back(apparatus::observe(*ar, d, pf, pred, pfirst, pframes));
    apparatus::ScopeRun run;
    run.start_ps = d.photon_ps(pfirst, 0, 0);
    run.end_ps = d.photon_ps(pfirst + pframes, 0, 0);
    // The VCD goes to a temporary name first, then is renamed (no half-written waveform).
    const fs::path vcd = out / "apparatus.vcd";
    run.vcd_path = (out / "apparatus.partial").string();
    run.vcd_shown = vcd.string();
    apparatus::ScopeEdges edges;
    try {
      edges = apparatus::run_oscilloscope(ps, ch, run);
    } catch (...) {
      discard_temp_file(run.vcd_path + ".vcd");
      throw;
    }
    fs::rename(run.vcd_path + ".vcd", vcd);
    write_text_atomic((out / "apparatus.gtkw").string(), gtkw_for_vcd(vcd.string(), "apparatus.vcd"));
    step("pendulum apparatus");
    md += "\n## The pendulum apparatus (Olano et al., figure 1), simulated\n\n"
          "Pendulum " + printf_text("%.0f", ps.amplitude_deg) + " deg, period " + printf_text("%.1f", ps.period_s) + " s, oscilloscope sampling every " +
          printf_text("%.1f", ps.scope_sample_s * 1e6) + " us; the screen photodiode at the centre. External: from the edges in apparatus.vcd; "
          "internal: the model's own timestamps for the refresh that made the edge.\n\n"
          "| architecture | passages | tracking (ms) | rendering (ms) | external total (ms) | internal total (ms) | largest disagreement (us) |\n"
          "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (size_t i = 0; i < ch.size(); ++i) {
      const auto m = apparatus::analyse(ps, edges, i, ch[i]);
      md += "| " + m.name + " | " + std::to_string(m.passages.size()) + " | " + printf_text("%.3f", m.mean_tracking_ms) + " | " +
            printf_text("%.3f", m.mean_rendering_ms) + " | " + printf_text("%.3f", m.mean_external_ms) + " | " + printf_text("%.3f", m.mean_internal_ms) + " | " +
            printf_text("%.1f", m.max_disagreement_ms * 1e3) + " |\n";
      summary["apparatus"].push_back({{"name", m.name},
                                      {"passages", m.passages.size()},
                                      {"tracking_ms", m.mean_tracking_ms},
                                      {"rendering_ms", m.mean_rendering_ms},
                                      {"external_total_ms", m.mean_external_ms},
                                      {"internal_total_ms", m.mean_internal_ms},
                                      {"max_disagreement_ms", m.max_disagreement_ms}});
    }
    md += "\nOpen the oscilloscope: `gtkwave " + vcd.string() + " " + (out / "apparatus.gtkw").string() + "`\n";
  }
  md += olano_reproduction(c, summary["olano"]);
  step("tables");
  write_text_atomic((out / "table.md").string(), md);
  write_text_atomic((out / "summary.json").string(), dump_json(summary, 2) + "\n");
  return md;
}


}  // namespace arp::lab
