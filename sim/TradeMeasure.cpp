#include "TradeMeasure.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "ConfigFile.hpp"
#include "HardwareCost.hpp"
#include "RunReport.hpp"
#include "Session.hpp"
#include "common/InputFile.hpp"
#include "common/ResourceUsage.hpp"
#include "common/StrictJson.hpp"
#include "common/Units.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "reference/accuracy/AccuracyHarness.hpp"
#include "reference/golden/GoldenReference.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::sim {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// kLevelTurnAxis as the motion option writes it.
std::string level_turn_axis() {
  char b[96];
  std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g", kLevelTurnAxis[0], kLevelTurnAxis[1], kLevelTurnAxis[2]);
  return b;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }


RunSpec level_run(const dp::ArpConfig& c, const std::string& fidelity, int64_t frames, const std::string& scratch) {
  RunSpec r;
  r.config = c;
  r.config_source = "trade point";
  r.fidelity = fidelity;
  r.motion.motion = "rotate";
  r.motion.axis = level_turn_axis();
  r.motion.rate = kLevelTurnDegS;
  r.frames = frames;
  r.out.out_dir = scratch;
  r.out.every = 0;
  return r;
}

RunSpec walk_run(const dp::ArpConfig& c, int64_t frames, int64_t error_every, const std::string& scratch) {
  RunSpec r;
  r.config = c;
  r.config_source = "trade point";
  r.memories.scene = "gallery";
  r.host.walk = "gallery";
  r.frames = frames;
  r.out.out_dir = scratch;
  r.out.every = 0;
  r.out.error_every = error_every;
  r.out.report = (fs::path(scratch) / "run.json").string();
  return r;
}

struct SessionOutcome {
  RunSummary summary;
  std::vector<std::string> pixel_hashes, photon_hashes;
  nlohmann::json report;  // when the spec asked for one
};

SessionOutcome run_session(RunSpec spec, const std::function<void(double, const std::string&)>& progress) {
  SessionOutcome out;
  Session session(std::move(spec));
  session.on_progress = [&](double f, const std::string& what) {
    if (progress) progress(f, what);
  };
  const int threads = session.spec().threads;
  session.on_frame = [&](const HmdFrame& f, const stage::FrameReport&) {
    FrameHashes h = frame_hashes(f, threads);
    out.pixel_hashes.push_back(std::move(h.pixels));
    out.photon_hashes.push_back(std::move(h.photons));
  };
  out.summary = session.run();
  if (!session.spec().out.report.empty()) out.report = parse_strict_json(read_input_file(session.spec().out.report, size_t{1} << 28, "run report"), session.spec().out.report);
  return out;
}

double value_or(const nlohmann::json& j, const char* key, double fallback = std::nan("")) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

// Display pixels per degree at the centre of the left eye's view, from the golden lens directions.
double centre_pixels_per_degree(const dp::ArpConfig& c) {
  const int x = c.timing.h_active / 2, y = c.timing.v_active / 2;
  const glm::dvec3 a = golden::lens_direction(c, 0, x, y), b = golden::lens_direction(c, 0, x + 1, y);
  const double deg = rad_to_deg(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
  return deg > 0 ? 1.0 / deg : 0.0;
}

nlohmann::json speed_figures(const RunSummary& s, const dp::ArpConfig& c) {
  const double sim_s = static_cast<double>(s.pixel_clocks) / static_cast<double>(c.timing.pixel_clock_hz);
  return {{"pixel_clocks", s.pixel_clocks},
          {"run_wall_s", s.wall_seconds},
          {"pixel_clocks_per_s", s.wall_seconds > 0 ? static_cast<double>(s.pixel_clocks) / s.wall_seconds : std::nan("")},
          {"real_time_fraction", s.wall_seconds > 0 ? sim_s / s.wall_seconds : std::nan("")}};
}

nlohmann::json measure_golden(const dp::ArpConfig& c, const TradeScale& s,
                              const std::function<void(double, const std::string&)>& progress) {
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  std::string source;
  MemoryContents{}.fill(mem, dp::Quat{}, source);
  const dp::VideoTiming timing(c.timing);
  const int64_t frames = s.level_frames();
  const glm::dvec3 axis = glm::normalize(glm::dvec3(kLevelTurnAxis[0], kLevelTurnAxis[1], kLevelTurnAxis[2]));
  const auto t0 = Clock::now();
  double checksum = 0;
  for (int64_t f = 0; f < frames; ++f) {
    const double t = (static_cast<double>(f) + 0.5) / timing.refresh_hz();
    const glm::dquat q = glm::angleAxis(deg_to_rad(kLevelTurnDegS * t), axis);
    const auto px = golden::frame(c, mem, q);
    checksum += px[px.size() / 2].x;  // keeps the frame from being optimised away
    if (progress) progress(static_cast<double>(f + 1) / static_cast<double>(frames), "golden frames");
  }
  const double wall = seconds_since(t0);
  const int64_t clocks = frames * timing.frame_cycles();
  const double sim_s = static_cast<double>(clocks) / static_cast<double>(c.timing.pixel_clock_hz);
  // Pixel clocks: whole frames (the timed levels count from the first scan-out to the last, 36 000 fewer over 6 frames).
  return {{"describes", "golden reference: double precision (GLM), exact face, texel and bilinear filter; untimed"},
          {"frames", frames},
          {"pixel_clocks", clocks},
          {"run_wall_s", wall},
          {"pixel_clocks_per_s", static_cast<double>(clocks) / wall},
          {"real_time_fraction", sim_s / wall},
          {"centre_checksum", checksum},
          {"timed", false}};
}

nlohmann::json measure_level(const TradePoint& p, const dp::ArpConfig& c, const TradeScale& s, const std::string& scratch,
                             const std::function<void(double, const std::string&)>& progress) {
  if (p.level == "golden") return measure_golden(c, s, progress);
  const SessionOutcome o = run_session(level_run(c, p.level, s.level_frames(), scratch), progress);
  nlohmann::json f = speed_figures(o.summary, c);
  scm::Fidelity fid{};
  scm::parse(p.level, fid);
  f["describes"] = scm::describe(fid);
  f["frames"] = o.summary.frames_done;
  f["timed"] = o.summary.cycle_accurate;
  f["latency_ps"] = {o.summary.latency_min_ps, o.summary.latency_median_ps, o.summary.latency_max_ps};
  f["underflows"] = o.summary.underflows;
  f["pixel_hashes"] = o.pixel_hashes;
  f["photon_hashes"] = o.photon_hashes;
  return f;
}

nlohmann::json measure_width(const dp::ArpConfig& c, const TradeScale& s, const std::string& scratch,
                             const std::function<void(double, const std::string&)>& progress) {
  accuracy::Options opt = accuracy_options(s);
  opt.progress = [&](const char* what, double f) {
    if (progress) progress(0.8 * f, what);
  };
  const accuracy::Report r = accuracy::run(c, opt);
  const SessionOutcome o = run_session(level_run(c, "functional", s.width_frames(), scratch), [&](double f, const std::string& w) {
    if (progress) progress(0.8 + 0.2 * f, w);
  });
  nlohmann::json f = speed_figures(o.summary, c);
  f["texel_max"] = r.overall.max_error;
  f["texel_mean"] = r.overall.mean_error();
  f["texel_exact_share"] = r.overall.exact_share();
  f["face_mismatches"] = r.overall.face_mismatch;
  f["samples"] = r.overall.samples;
  // Per view, not only pooled: the worst generic view, and the views aligned with the cube axes (ties apart).
  const int worst = accuracy::worst_view(r, false);
  if (worst >= 0) {
    const accuracy::Stats& w = r.views[static_cast<size_t>(worst)].stats;
    f["worst_view"] = r.views[static_cast<size_t>(worst)].view.name;
    f["worst_view_exact_share"] = w.exact_share_nontie();
    f["worst_view_max"] = w.max_error;
  }
  f["aligned_exact_share_nontie"] = r.aligned.exact_share_nontie();
  f["aligned_max"] = r.aligned.max_error;
  f["aligned_ties"] = r.aligned.ties;
  f["color_max_lsb"] = r.color.max_error;
  f["color_p999_lsb"] = r.color.p999_error;
  f["color_mean_lsb"] = r.color.mean_error;
  const HardwareCost cost = hardware_cost(c);
  f["cost"] = {{"synthesized_configuration", cost.configuration()},
               {"fully_synthesized", cost.fully_synthesized()},
               {"modules_synthesized", cost.synthesized.size()},
               {"cells", cost.cells()},
               {"ice40_lut4", cost.lut4()},
               {"logic_depth", cost.logic_depth()},
               {"model_multiplier_bits", cost.model.multiplier_bits},
               {"model_adder_bits", cost.model.adder_bits},
               {"model_table_bits", cost.model.table_bits}};
  return f;
}

nlohmann::json measure_walk(const TradePoint& p, const dp::ArpConfig& c, const TradeScale& s, const std::string& scratch,
                            const std::function<void(double, const std::string&)>& progress) {
  RunSpec spec = walk_run(c, s.host_frames(), s.host_error_every(), scratch);
  spec.host.threshold_deg = p.theta_deg;
  if (p.region_m > 0) {
    spec.config.memory.region_size_m = p.region_m;
    spec.config.memory.region_margin_m = host::swept_margin_m(p.region_m);
  }
  const SessionOutcome o = run_session(spec, progress);
  const nlohmann::json& h = o.report.at("host");
  const nlohmann::json err = h.contains("error") ? h["error"] : nlohmann::json::object();
  nlohmann::json f = speed_figures(o.summary, c);
  f["threshold_deg"] = value_or(h, "threshold_deg");
  f["triangles_per_s"] = value_or(h, "triangles_per_s");
  f["full_render_triangles_per_s"] = value_or(h, "full_render_every_frame_triangles_per_s");
  f["load_reduction"] = value_or(h, "load_reduction");
  f["host_wall_ms_per_frame"] = value_or(h, "host_wall_ms_per_frame");
  f["frames_measured"] = value_or(err, "frames_measured");
  f["mean_psnr_db"] = value_or(err, "mean_psnr_db");
  f["worst_psnr_db"] = value_or(err, "worst_psnr_db");
  f["max_displacement_px"] = value_or(err, "max_displacement_px");
  f["worst_share_another_object"] = value_or(err, "worst_share_showing_another_object");
  f["mean_tear_pixels"] = value_or(err, "mean_tear_pixels");
  return f;
}

nlohmann::json measure_latency(const TradePoint& p, const dp::ArpConfig& c, const TradeScale& s, const std::string& scratch,
                               const std::function<void(double, const std::string&)>& progress) {
  RunSpec spec = walk_run(c, s.latency_frames(), 0, scratch);
  spec.stalls = p.stalls;
  spec.fidelity = "cycle";
  spec.motion.motion = "rotate";
  spec.motion.axis = "0,1,0";
  spec.motion.rate = kTradeHeadSpeedDegS;
  const SessionOutcome o = run_session(spec, progress);
  const RunSummary& r = o.summary;
  nlohmann::json f = speed_figures(r, c);
  f["latency_ps"] = {r.latency_min_ps, r.latency_median_ps, r.latency_max_ps};
  f["underflows"] = r.underflows;
  f["late_discarded"] = r.late_discarded;
  f["orientation_lead_ns"] = value_or(o.report.at("pipeline"), "orientation_lead_ns", std::nan(""));
  f["refresh_hz"] = dp::VideoTiming(c.timing).refresh_hz();
  // Under a steady turn at w the pixel shows the world where the head was `latency` earlier: w x latency,
  // in display pixels at the view's centre (the latency from the modelled timeline, the scale from the golden lens).
  const double ppd = centre_pixels_per_degree(c);
  f["pixels_per_degree"] = ppd;
  auto reg = [&](int64_t ps) { return kTradeHeadSpeedDegS * static_cast<double>(ps) * 1e-12 * ppd; };
  f["registration_px"] = {reg(r.latency_min_ps), reg(r.latency_median_ps), reg(r.latency_max_ps)};
  const HardwareCost cost = hardware_cost(c);
  f["cells"] = cost.fully_synthesized() ? nlohmann::json(cost.cells()) : nlohmann::json();
  f["fifo_depth"] = c.timed.fifo_depth;
  return f;
}

}  // namespace

accuracy::Options accuracy_options(const TradeScale& s) {
  accuracy::Options o;
  if (s.quick) {
    o.frame_orientations = 1;
    o.random_orientations = 8;
    o.random_pixels = 2048;
    o.color_orientations = 1;
  }
  return o;
}

dp::ArpConfig trade_config(const TradePoint& p) { return config::resolve("", p.sets); }

std::string machine_description() {
  std::string model = "unknown CPU";
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) model = line.substr(colon + 2);
      break;
    }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

nlohmann::json measure_trade_point(const TradePoint& p, const TradeScale& s, const std::string& scratch,
                                   const std::function<void(double, const std::string&)>& progress) {
  const dp::ArpConfig c = trade_config(p);
  fs::create_directories(scratch);
  const auto t0 = Clock::now();
  nlohmann::json figures;
  switch (p.kind) {
    case TradeKind::Level: figures = measure_level(p, c, s, scratch, progress); break;
    case TradeKind::Width: figures = measure_width(c, s, scratch, progress); break;
    case TradeKind::Theta:
    case TradeKind::Region: figures = measure_walk(p, c, s, scratch, progress); break;
    case TradeKind::Latency: figures = measure_latency(p, c, s, scratch, progress); break;
  }
  std::error_code ec;
  fs::remove_all(scratch, ec);
  return {{"id", p.id},
          {"table", trade_kind_key(p.kind)},
          {"label", p.label},
          {"sets", p.sets},
          {"stalls", p.stalls},
          {"quick", s.quick},
          {"machine", machine_description()},
          {"point_wall_s", seconds_since(t0)},
          {"peak_rss_bytes", peak_resident_bytes()},
          {"figures", figures}};
}

}  // namespace arp::sim
