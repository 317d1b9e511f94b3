// arpsim run: a head-motion trace (or synthetic motion) through the pipeline
// at a chosen fidelity level -- the untimed functional model, loosely timed,
// fast cycle-accurate or detailed cycle-accurate SystemC -- writing frames as
// images, a JSON report, a per-frame CSV, optionally each pixel's photon time
// and a VCD waveform with a matching GTKWave save file.
#include <algorithm>
#include <chrono>
#include <numeric>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "FrameImage.hpp"
#include "GtkwSaveFile.hpp"
#include "MotionOptions.hpp"
#include "PoseConversion.hpp"
#include "TruthProbe.hpp"
#include "sim/ConfigFile.hpp"
#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "host/priority/HostSimulation.hpp"
#include "host/regions/Segmentation.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/SceneFile.hpp"
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include "rtl_model/systemc/TimedRun.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/TraceFile.hpp"
#include "common/Units.hpp"

namespace arp::app {

namespace {

namespace fs = std::filesystem;

struct RunArgs {
  ConfigOptions cfg;
  CubeMapOptions cubemap;
  MotionOptions motion;
  std::string fidelity = "functional";
  std::string trace, out_dir = "run", report, csv, vcd, vcd_lines, vcd_time_us, host_csv, tear_image, tear_at, live;
  std::vector<std::string> stalls;
  bool no_speculation = false;
  std::string walk;
  double walk_speed = 0, threshold_deg = 0;
  bool baseline = false;
  int64_t error_every = 10;
  double region_size = 0, margin = 0.5, warp_falloff = 0;
  bool no_segmentation = false, warp = false, region_cubes = false;
  host::RenderEngine engine;
  int64_t frames = 60, first = 0, every = 1;
  int threads = 0;
  bool photon_times = false, quiet = false;
};

// A word-wise FNV-1a style fingerprint, so levels run in different
// processes can be compared exactly (equal frames give equal hashes).
uint64_t fnv(uint64_t h, uint64_t v) { return (h ^ v) * 0x100000001b3ull; }

// "A:B" -> two numbers; InputError naming the option otherwise.
std::pair<double, double> parse_window(const std::string& opt, const std::string& s) {
  const auto colon = s.find(':');
  try {
    if (colon == std::string::npos) throw std::invalid_argument("");
    size_t n1 = 0, n2 = 0;
    const double a = std::stod(s.substr(0, colon), &n1), b = std::stod(s.substr(colon + 1), &n2);
    if (n1 != colon || n2 != s.size() - colon - 1 || !(b > a)) throw std::invalid_argument("");
    return {a, b};
  } catch (const std::exception&) {
    throw InputError(opt, s, "expected START:END with END > START");
  }
}

// The VCD's final path (".vcd" added; a bare name goes into waveforms/) and its directory made.
std::string vcd_path(const std::string& arg) {
  fs::path p(arg);
  if (!p.has_parent_path()) p = fs::path("waveforms") / p;
  if (p.extension() != ".vcd") p += ".vcd";
  std::error_code ec;
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  std::ofstream probe(p.string() + ".probe");
  if (!probe) throw InputError(p.string(), "", "cannot write the waveform there");
  probe.close();
  fs::remove(p.string() + ".probe", ec);
  return p.string();
}

std::string frame_csv_header() {
  return "frame,pixels,underflows,late_discarded,reset_pixels,latency_min_ns,latency_median_ns,latency_max_ns,"
         "first_photon_ps,last_photon_ps,pixel_hash,photon_hash\n";
}

int run(const RunArgs& a) {
  dp::ArpConfig c = a.cfg.resolve();
  scm::Fidelity fid;
  if (!scm::parse(a.fidelity, fid)) throw InputError("--fidelity", a.fidelity, "must be functional, lt, cycle or rtl");
  if (a.frames < 1 || a.frames > 1'000'000) throw InputError("--frames", "", "must be 1 .. 1000000");
  if (a.first < 0 || a.first > 1'000'000'000) throw InputError("--first-frame", "", "must be 0 .. 1e9");
  if (a.every < 0) throw InputError("--every", "", "must be >= 0 (0: no images)");
  if (!a.trace.empty() && a.motion.given()) throw InputError("--trace", "", "give either --trace or --motion, not both");
  if (!a.live.empty()) {
    if (a.live != "usb") throw InputError("--live", a.live, "the live source is usb (an Oculus Rift DK1/DK2)");
    if (!a.trace.empty() || a.motion.given() || !a.walk.empty())
      throw InputError("--live", "", "live input replaces --trace, --motion and --walk");
    if (fid != scm::Fidelity::Functional)
      throw InputError("--live", "", "live input drives the functional level (the timed levels read their orientation trace ahead)");
  }
  if (!a.host_csv.empty() && (a.report.empty() || a.walk.empty())) throw InputError("--host-csv", "", "needs --walk and --report");
  if (!a.vcd.empty() && fid == scm::Fidelity::Functional)
    throw InputError("--vcd", "", "the functional level is untimed and has no waveform; use --fidelity lt, cycle or rtl");
  if ((!a.vcd_lines.empty() || !a.vcd_time_us.empty()) && a.vcd.empty())
    throw InputError(a.vcd_lines.empty() ? "--vcd-time-us" : "--vcd-lines", "", "needs --vcd");
  if (!a.tear_image.empty() && (a.region_size == 0 || a.error_every <= 0 || a.walk.empty()))
    throw InputError("--tear-image", "", "needs --walk, --regions and --error-every > 0 (tearing is measured against the truth)");
  if (a.region_cubes && a.region_size == 0) throw InputError("--region-cubes", "", "needs --regions SIZE");
  if (!a.tear_at.empty() && a.tear_image.empty()) throw InputError("--tear-at", "", "needs --tear-image");
  const auto issues = fid == scm::Fidelity::Functional ? dp::validate(c) : dp::validate_timed(c);
  if (!issues.empty()) throw InputError(a.cfg.file.empty() ? "configuration" : a.cfg.file, issues.front().key, issues.front().reason);

  const dp::VideoTiming t(c.timing);
  const int64_t start_ps = t.cycles_to_ps(t.frame_start_cycle(a.first));
  const int64_t end_ps = t.cycles_to_ps(t.frame_start_cycle(a.first + a.frames));
  std::vector<tracker::PoseSample> poses;
  std::string motion_source = "still head";
  if (!a.trace.empty()) {
    poses = tracker::read_trace_csv(a.trace);
    motion_source = a.trace;
  } else if (a.motion.given()) {
    // A second of margin before the first frame covers every lead; 10 ms after the last covers the sampling.
    poses = a.motion.make(static_cast<double>(start_ps) * 1e-12 - 1.0, static_cast<double>(end_ps - start_ps) * 1e-12 + 1.01);
    motion_source = "synthetic " + a.motion.motion;
  }
  // A walk: the head moves along it and faces where it goes; head motion or a trace turns it on top.
  std::unique_ptr<host::WalkPath> walk;
  if (!a.walk.empty()) {
    if (a.cubemap.scene.empty()) throw InputError("--walk", "", "needs --scene (what to walk through)");
    if (a.walk == "gallery") walk = std::make_unique<host::WalkPath>(host::gallery_walk(), a.walk_speed > 0 ? a.walk_speed : 1.0, "gallery walk");
    else {
      walk = std::make_unique<host::WalkPath>(host::load_walk_file(a.walk));
      if (a.walk_speed > 0) *walk = host::WalkPath(walk->points(), a.walk_speed, a.walk);
    }
    if (poses.empty()) {  // still head on the walk: sample it at 1 kHz
      const double t0 = static_cast<double>(start_ps) * 1e-12 - 1.0, t1 = static_cast<double>(end_ps) * 1e-12 + 0.01;
      for (double tt = t0; tt <= t1; tt += 1e-3) {
        tracker::PoseSample p;
        p.time_ps = static_cast<int64_t>(std::llround(tt * 1e12));
        poses.push_back(p);
      }
    }
    for (auto& p : poses) {
      const double tt = static_cast<double>(p.time_ps) * 1e-12;
      const glm::dvec3 v = walk->velocity(tt);
      const double yaw = std::atan2(-v.x, -v.z);  // yaw 0 looks down -z; positive turns left
      p.orientation = glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * p.orientation;
    }
    motion_source = (a.walk == "gallery" ? std::string("gallery walk") : a.walk) + " with " + motion_source;
  }
  std::vector<dp::OrientationSample> samples = to_orientation_samples(poses);
  // Live input starts from the identity and grows frame by frame as the device's samples arrive.
  std::unique_ptr<tracker::PoseSource> live;
  if (!a.live.empty()) {
    std::string err;
    live = tracker::usb_source(err);
    if (!live) {
      std::fprintf(stderr, "arpsim run: --live usb: %s\n", err.c_str());
      return 1;
    }
    motion_source = "live " + live->describe();
  }
  dp::OrientationStream stream = samples.empty() ? dp::OrientationStream::constant(dp::Quat{})
                                                 : dp::OrientationStream(std::move(samples), motion_source);

  std::string source;
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  std::unique_ptr<host::Scene> scene;
  std::unique_ptr<host::HostSimulation> hostsim;
  std::unique_ptr<host::RegionGrid> grid;
  std::unique_ptr<host::RegionScheduler> regions;
  host::Segmented segmented;
  if (walk) {
    scene = std::make_unique<host::Scene>(a.cubemap.scene == "gallery" ? host::make_gallery() : host::load_scene_file(a.cubemap.scene));
    for (const auto& n : scene->notes) std::fprintf(stderr, "arpsim: note: %s\n", n.c_str());
    host::PriorityConfig pc;
    pc.memories = c.memory.count;
    pc.display_hz = t.refresh_hz();
    pc.baseline = a.baseline;
    if (!(a.threshold_deg >= 0) || a.threshold_deg > 90) throw InputError("--threshold-deg", "", "must be 0 .. 90 degrees (0: one texel)");
    pc.threshold_rad = deg_to_rad(a.threshold_deg);
    for (auto [name, v] : {std::pair<const char*, double>{"--engine-triangles", a.engine.triangles_per_s},
                           {"--engine-fill", a.engine.pixels_per_s}})
      if (!(v > 0) || !std::isfinite(v)) throw InputError(name, "", "must be a positive rate");
    if (!(a.engine.object_setup_s >= 0) || !std::isfinite(a.engine.object_setup_s)) throw InputError("--engine-setup", "", "must be >= 0");
    auto head = [&stream](double tt) {
      const dp::Quat& q = stream[stream.index_at(static_cast<int64_t>(std::llround(tt * 1e12)))].q;
      return glm::dquat(q.w, q.x, q.y, q.z);
    };
    if (a.region_size != 0) {
      // Region priority rendering: the world in columns, large objects cut along them.
      grid = std::make_unique<host::RegionGrid>(scene->extent_min, scene->extent_max, a.region_size, a.region_cubes, "--regions");
      segmented = host::segment_scene(*scene, *grid, !a.no_segmentation);
      scene = std::make_unique<host::Scene>(std::move(segmented.scene));
      host::RegionConfig rc;
      rc.region_size_m = a.region_size;
      rc.margin_m = a.margin;
      rc.memories = c.memory.count;
      rc.threshold_rad = pc.threshold_rad;
      regions = std::make_unique<host::RegionScheduler>(*grid, rc, c.memory.face_size,
                                                         walk->position(static_cast<double>(start_ps) * 1e-12), "--margin");
    }
    hostsim = std::make_unique<host::HostSimulation>(*scene, pc, a.engine, *walk, head, mem, a.cubemap.ipd_m, t.refresh_hz());
    if (regions) {
      hostsim->use_regions(regions.get(), segmented.region, segmented.span);
      if (!(a.warp_falloff >= 0) || a.warp_falloff > a.region_size) throw InputError("--warp-falloff", "", "must be 0 .. the region size");
      hostsim->use_warping(a.warp, a.warp_falloff > 0 ? a.warp_falloff : a.region_size / 2);
    } else if (a.warp) {
      throw InputError("--warp", "", "region warping needs --regions");
    }
    hostsim->prime(static_cast<double>(start_ps) * 1e-12);
    source = "scene " + scene->name + " (" + std::to_string(scene->objects.size()) + " objects, " +
             std::to_string(scene->triangles()) + " triangles), host rendering " + (a.baseline ? "everything every frame (baseline)" : "by priority");
  } else {
    a.cubemap.fill(mem, stream[stream.index_at(start_ps)].q, source);
  }
  std::error_code ec;
  if (a.every > 0 || a.photon_times) {
    fs::create_directories(a.out_dir, ec);
    if (ec || !fs::is_directory(a.out_dir))
      throw InputError(a.out_dir, "", "cannot create the output folder" + (ec ? ": " + ec.message() : std::string()));
  }

  scm::TimedRunOptions opt;
  opt.fidelity = fid;
  opt.threads = a.threads;
  std::string vcd_final, vcd_tmp_base;
  if (!a.vcd.empty()) {
    vcd_final = vcd_path(a.vcd);
    vcd_tmp_base = temp_path_beside(vcd_final).string();
    opt.vcd.path = vcd_tmp_base;
    if (!a.vcd_lines.empty()) {
      const auto [l0, l1] = parse_window("--vcd-lines", a.vcd_lines);
      if (l0 < 0 || l0 != std::floor(l0) || l1 != std::floor(l1)) throw InputError("--vcd-lines", a.vcd_lines, "lines must be whole numbers >= 0");
      const int64_t base = t.frame_start_cycle(a.first);
      opt.vcd.from_ps = t.cycles_to_ps(base + static_cast<int64_t>(l0) * c.timing.h_total());
      opt.vcd.to_ps = t.cycles_to_ps(base + static_cast<int64_t>(l1) * c.timing.h_total());
    } else if (!a.vcd_time_us.empty()) {
      const auto [t0, t1] = parse_window("--vcd-time-us", a.vcd_time_us);
      opt.vcd.from_ps = static_cast<int64_t>(std::llround(t0 * 1e6));
      opt.vcd.to_ps = static_cast<int64_t>(std::llround(t1 * 1e6));
    }
  }

  std::vector<stage::StallWindow> stalls;
  for (const std::string& spec : a.stalls) {
    // STAGE:CLOCK:CYCLES, CLOCK counted from the first frame's first active pixel.
    const auto c1 = spec.find(':'), c2 = spec.find(':', c1 == std::string::npos ? 0 : c1 + 1);
    stage::StallWindow w{dp::Stage::Lens, 0, 0};
    bool ok = c1 != std::string::npos && c2 != std::string::npos;
    if (ok) {
      const std::string stage = spec.substr(0, c1);
      ok = false;
      for (int k = 0; k + 1 < dp::kStageCount; ++k)
        if (stage == dp::stage_key(static_cast<dp::Stage>(k))) {
          w.stage = static_cast<dp::Stage>(k);
          ok = true;
        }
      try {
        size_t n1 = 0, n2 = 0;
        const std::string a1 = spec.substr(c1 + 1, c2 - c1 - 1), a2 = spec.substr(c2 + 1);
        w.first_cycle = t.frame_start_cycle(a.first) + std::stoll(a1, &n1);
        w.cycles = std::stoll(a2, &n2);
        ok = ok && n1 == a1.size() && n2 == a2.size() && w.cycles > 0 && w.cycles <= 1'000'000'000;
      } catch (const std::exception&) {
        ok = false;
      }
    }
    if (!ok)
      throw InputError("--stall", spec,
                       "expected STAGE:CLOCK:CYCLES with STAGE one of lens, rotate, address, fetch, compose, filter "
                       "and CYCLES >= 1");
    if (fid != scm::Fidelity::Rtl && fid != scm::Fidelity::Cycle)
      throw InputError("--stall", spec, "stalls exist only at the cycle-accurate levels (cycle, rtl)");
    stalls.push_back(w);
  }
  opt.speculate = !a.no_speculation;

  ProgressLine progress("run " + a.fidelity, !a.quiet);
  opt.progress = [&progress](double f, const std::string& what) { progress.update(f, what); };

  stage::TimedInputs in;
  in.config = c;
  in.memories = &mem;
  in.orientation = &stream;
  // Live: before each frame, take what the device has sent until the frame's
  // end on the wall clock (the run goes at the display's pace), placed on
  // the run's timeline; an unplug holds the last pose and the run goes on.
  int64_t live_offset_ps = 0, live_samples = 0;
  if (live) {
    const auto wall0 = std::chrono::steady_clock::now();
    live_offset_ps = start_ps - live->now_ps();  // a pose that arrives as frame `first` starts is placed at its start
    auto got_ptr = std::make_shared<std::vector<tracker::PoseSample>>();  // lives as long as the hook
    in.before_frame = [&, wall0, got_ptr](int64_t frame, double) {
      std::vector<tracker::PoseSample>& got = *got_ptr;
      const int64_t until_ps = t.cycles_to_ps(t.frame_start_cycle(frame + 1)) - start_ps;
      for (;;) {
        const int64_t wall_ps = static_cast<int64_t>(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count() * 1e12);
        if (wall_ps >= until_ps) break;
        live->poll(got, static_cast<int>(std::min<int64_t>(5, (until_ps - wall_ps) / 1'000'000'000 + 1)));
      }
      for (const auto& e : live->take_events()) std::fprintf(stderr, "arpsim run: live input %s\n", e.c_str());
      live_samples += append_live_poses(stream, got, live_offset_ps, motion_source);
      got.clear();
    };
  }
  in.first_frame = a.first;
  in.frames = a.frames;
  in.stalls = stalls;
  int64_t baseline_triangles = 0;
  double host_wall_s = 0;  // our own host code: scheduling and rendering
  if (hostsim)
    in.before_frame = [&](int64_t frame, double tt) {
      const auto w0 = std::chrono::steady_clock::now();
      hostsim->before_frame(frame, tt);
      host_wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
      baseline_triangles += hostsim->full_render_triangles(tt);
    };
  nlohmann::json frames = nlohmann::json::array();
  std::string csv = frame_csv_header();
  int images = 0;
  // Error against the truth (TruthProbe): every --error-every-th frame of a walk.
  std::unique_ptr<TruthProbe> probe;
  if (hostsim && a.error_every > 0) {
    TruthProbeSetup ps;
    ps.config = &c;
    ps.scene = scene.get();
    ps.walk = walk.get();
    ps.host = hostsim.get();
    ps.memories = &mem;
    ps.orientation = &stream;
    ps.segmented = regions ? &segmented : nullptr;
    ps.ipd_m = a.cubemap.ipd_m;
    ps.threads = a.threads;
    ps.first_frame = a.first;
    ps.frames = a.frames;
    ps.every = a.error_every;
    ps.tear_image = a.tear_image;
    ps.tear_at = a.tear_at;
    probe = std::make_unique<TruthProbe>(ps);
  }
  const dp::LatchRule latch_rule(c);
  const double px_rad = deg_to_rad(c.lens.fov_deg) / c.timing.h_active;
  in.sink = [&](const HmdFrame& f, const stage::FrameReport& r) {
    uint64_t ph = 0xcbf29ce484222325ull, th = ph;
    for (uint32_t p : f.pixels) ph = fnv(ph, p);
    for (int64_t p : f.photon_ps) th = fnv(th, static_cast<uint64_t>(p));
    const int64_t k = r.frame - a.first;
    if (a.every > 0 && k % a.every == 0) {
      char name[64];
      std::snprintf(name, sizeof name, "frame_%06" PRId64 ".png", r.frame);
      host::write_rgb8((fs::path(a.out_dir) / name).string(), frame_to_image(f));
      ++images;
      if (a.photon_times) {
        std::snprintf(name, sizeof name, "photon_%06" PRId64 ".csv", r.frame);
        std::string text = "eye,x,y,photon_ps\n";
        for (int e = 0; e < f.eyes; ++e)
          for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
              text += std::to_string(e) + "," + std::to_string(x) + "," + std::to_string(y) + "," +
                      std::to_string(f.photon_ps[f.index(e, x, y)]) + "\n";
        write_text_atomic((fs::path(a.out_dir) / name).string(), text);
      }
    }
    char hex[2][24];
    std::snprintf(hex[0], sizeof hex[0], "%016" PRIx64, ph);
    std::snprintf(hex[1], sizeof hex[1], "%016" PRIx64, th);
    // The samples the frame's latches can take: from its first latch to the next frame's.
    const auto [lo, hi] = latch_rule.frame_samples(stream, r.frame);
    nlohmann::json err;
    if (probe && (r.frame - a.first) % a.error_every == 0) probe->measure(f, r.frame, err);
    frames.push_back({{"frame", r.frame},
                      {"first_sample", lo},
                      {"last_sample", hi},
                      {"pixels", r.pixels},
                      {"underflows", r.underflows},
                      {"late_discarded", r.late_discarded},
                      {"reset_pixels", r.reset_pixels},
                      {"latency_ps", {{"min", r.latency_min_ps}, {"median", r.latency_median_ps}, {"max", r.latency_max_ps}}},
                      {"first_photon_ps", r.first_photon_ps},
                      {"last_photon_ps", r.last_photon_ps},
                      {"pixel_hash", hex[0]},
                      {"photon_hash", hex[1]}});
    if (!err.is_null()) frames.back()["error"] = err["error"];
    char row[512];
    std::snprintf(row, sizeof row, "%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%.3f,%.3f,%.3f,%" PRId64 ",%" PRId64 ",%s,%s\n",
                  r.frame, r.pixels, r.underflows, r.late_discarded, r.reset_pixels, r.latency_min_ps * 1e-3,
                  r.latency_median_ps * 1e-3, r.latency_max_ps * 1e-3, r.first_photon_ps, r.last_photon_ps, hex[0], hex[1]);
    csv += row;
  };

  scm::TimedResult res;
  try {
    res = scm::run_timed(in, opt);
  } catch (...) {
    if (!vcd_tmp_base.empty()) discard_temp_file(vcd_tmp_base + ".vcd");
    throw;
  }
  if (!vcd_final.empty()) {
    commit_temp_file(vcd_tmp_base + ".vcd", vcd_final);
    const std::string gtkw = fs::path(vcd_final).replace_extension(".gtkw").string();
    write_text_atomic(gtkw, gtkw_for_vcd(vcd_final, fs::path(vcd_final).filename().string()));
  }

  const double mcps = res.cycles_per_second() * 1e-6;
  int64_t worst_lat = 0, best_lat = INT64_MAX;
  std::vector<int64_t> medians;
  for (const auto& f : res.frames) {
    worst_lat = std::max(worst_lat, f.latency_max_ps);
    best_lat = std::min(best_lat, f.latency_min_ps);
    medians.push_back(f.latency_median_ps);
  }
  std::sort(medians.begin(), medians.end());
  std::printf("arpsim run: %s level, %" PRId64 " frames (%" PRId64 "..%" PRId64 ") of %s with %s\n", a.fidelity.c_str(),
              a.frames, a.first, a.first + a.frames - 1, motion_source.c_str(), source.c_str());
  std::printf("  orientation sample -> photon: min %.1f us, median %.1f us, max %.1f us\n", best_lat * 1e-6,
              medians[medians.size() / 2] * 1e-6, worst_lat * 1e-6);
  if (fid == scm::Fidelity::Rtl || fid == scm::Fidelity::Cycle)
    std::printf("  underflows %" PRId64 ", late pixels dropped %" PRId64 ", buffer swaps %" PRId64 "\n", res.underflows,
                res.late_discarded, res.swaps);
  std::printf("  %" PRId64 " pixel clocks in %.2f s: %.2f M pixel clocks/s\n", res.end_cycle - res.first_cycle,
              res.wall_seconds, mcps);
  if (images) std::printf("  %d images in %s\n", images, a.out_dir.c_str());
  if (!vcd_final.empty()) std::printf("  waveform %s (open: gtkwave %s %s)\n", vcd_final.c_str(), vcd_final.c_str(),
                                      fs::path(vcd_final).replace_extension(".gtkw").c_str());
  if (!poses.empty() && poses.back().time_ps < end_ps)
    std::printf("  note: the trace ends at %.6f s; later pixels hold its last sample (sample-and-hold)\n",
                static_cast<double>(poses.back().time_ps) * 1e-12);

  if (!a.tear_image.empty() && probe) std::printf("%s", probe->write_tear_image().c_str());
  if (!a.csv.empty()) write_text_atomic(a.csv, csv);
  if (!a.report.empty()) {
    const auto& tm = c.timed;
    const double period_ns = 1e9 / static_cast<double>(c.timing.pixel_clock_hz);
    nlohmann::json stages = nlohmann::json::array();
    for (int s = 0; s < dp::kStageCount; ++s) {
      const auto& st = res.stages[static_cast<size_t>(s)];
      const int lat = tm.stage[static_cast<size_t>(s)].latency_cycles;
      nlohmann::json j{{"stage", dp::stage_key(static_cast<dp::Stage>(s))},
                       {"latency_cycles", lat},
                       {"latency_ns", lat * period_ns}};
      if (res.stages_measured && s < dp::kStageCount - 1)
        j["measured"] = {{"pixels", st.pixels},         {"min_cycles", st.min_cycles},
                         {"mean_cycles", st.mean_cycles}, {"max_cycles", st.max_cycles},
                         {"stalled_cycles", st.stalled_cycles}};
      stages.push_back(j);
    }
    nlohmann::json fifos = nlohmann::json::array();
    for (const auto& [name, f] : res.fifos)
      fifos.push_back({{"fifo", name},          {"depth", f.depth},           {"writes", f.writes},
                       {"max_occupancy", f.max_occupancy}, {"mean_occupancy", f.mean_occupancy},
                       {"full_cycles", f.full_cycles},     {"empty_cycles", f.empty_cycles},
                       {"blocked_writes", f.blocked_writes}});
    nlohmann::json jobs = nlohmann::json::array();
    for (const auto& j : res.host_jobs)
      jobs.push_back({{"start_ps", j.start_ps}, {"commit_ps", j.commit_ps}, {"swap_ps", j.swap_ps}, {"swap_frame", j.swap_frame}});
    nlohmann::json r{
        {"fidelity", a.fidelity},
        {"fidelity_description", scm::describe(fid)},
        {"motion", motion_source},
        {"cube_map", source},
        {"frames", frames},
        {"pipeline",
         {{"issue_lead_cycles", res.issue_lead},
          {"issue_lead_ns", res.issue_lead * period_ns},
          {"orientation_lead_cycles", res.orientation_lead},
          {"orientation_lead_ns", res.orientation_lead * period_ns},
          {"stages", stages}}},
        {"fifos_modelled", res.fifos_modelled},
        {"fifos", fifos},
        {"underflows", res.underflows},
        {"late_discarded", res.late_discarded},
        {"issue_stalls", res.issue_stalls},
        {"buffer_swaps", res.swaps},
        {"host_jobs", jobs},
        {"orientation_writes", res.orientation_writes},
        {"simulation",
         {{"pixel_clocks", res.end_cycle - res.first_cycle},
          {"wall_seconds", res.wall_seconds},
          {"pixel_clocks_per_second", res.cycles_per_second()},
          {"speculated_pixels", res.speculated_pixels},
          {"fallback_pixels", res.fallback_pixels},
          {"vcd_time_zero_ps", t.cycles_to_ps(res.first_cycle)},
          {"vcd", vcd_final}}},
        {"images", images},
        {"config", config::to_json(c)}};
    if (live) {
      tracker::StreamStats st;
      live->usb_stats(st);
      r["live"] = {{"source", motion_source}, {"samples", live_samples}, {"reports", st.reports}, {"malformed", st.malformed},
                   {"disconnects", st.disconnects}, {"reconnects", st.reconnects}, {"keep_alives", st.keep_alives},
                   {"connected_at_end", live->connected()}};
    }
    if (hostsim) {
      const double secs = static_cast<double>(a.frames) / t.refresh_hz();
      nlohmann::json mems = nlohmann::json::array();
      int64_t tris = 0;
      for (size_t m = 0; m < hostsim->load().size(); ++m) {
        const auto& L = hostsim->load()[m];
        tris += L.triangles;
        const double n = L.updates > 0 ? static_cast<double>(L.updates) : 1.0;
        mems.push_back({{"memory", m},
                        {"objects_now", hostsim->scheduler().objects_in(static_cast<int>(m)).size()},
                        {"updates", L.updates},
                        {"skipped_overload", L.skipped},
                        {"update_rate_hz", static_cast<double>(L.updates) / secs},
                        {"objects_per_update", static_cast<double>(L.objects) / n},
                        {"triangles_per_update", static_cast<double>(L.triangles) / n},
                        {"triangles_per_s", static_cast<double>(L.triangles) / secs},
                        {"texels_per_s", static_cast<double>(L.texels) / secs},
                        {"engine_busy_s", L.busy_s}});
      }
      r["host"] = {{"threshold_deg", rad_to_deg(hostsim->scheduler().threshold_rad())},
                   {"mode", regions ? "regions" : (a.baseline ? "baseline" : "objects")},
                   {"baseline", a.baseline},
                   {"engine", {{"triangles_per_s", a.engine.triangles_per_s}, {"pixels_per_s", a.engine.pixels_per_s},
                               {"object_setup_s", a.engine.object_setup_s}}},
                   {"memories", mems},
                   {"object_moves", hostsim->scheduler().moves()},
                   {"triangles_per_s", static_cast<double>(tris) / secs},
                   {"full_render_every_frame_triangles_per_s", static_cast<double>(baseline_triangles) / secs},
                   {"load_reduction", tris > 0 ? static_cast<double>(baseline_triangles) / static_cast<double>(tris) : 0.0},
                   {"host_wall_ms_per_frame", 1e3 * host_wall_s / static_cast<double>(a.frames)}};
      if (!a.host_csv.empty()) {
        std::string hc = "memory,updates,skipped_overload,update_rate_hz,objects_per_update,triangles_per_update,triangles_per_s,texels_per_s\n";
        for (const auto& m : mems)
          hc += std::to_string(m["memory"].get<int>()) + "," + std::to_string(m["updates"].get<int64_t>()) + "," +
                std::to_string(m["skipped_overload"].get<int64_t>()) + "," + std::to_string(m["update_rate_hz"].get<double>()) +
                "," + std::to_string(m["objects_per_update"].get<double>()) + "," +
                std::to_string(m["triangles_per_update"].get<double>()) + "," + std::to_string(m["triangles_per_s"].get<double>()) +
                "," + std::to_string(m["texels_per_s"].get<double>()) + "\n";
        write_text_atomic(a.host_csv, hc);
      }
      if (regions)
        r["host"]["regions"] = {{"size_m", a.region_size},
                                {"margin_m", a.margin},
                                {"shape", a.region_cubes ? "cubes" : "columns"},
                                {"regions", grid->count()},
                                {"segmentation", !a.no_segmentation},
                                {"objects_cut", segmented.objects_cut},
                                {"segments", segmented.segments},
                                {"objects_after_segmentation", scene->objects.size()},
                                {"reassignments", regions->reassignments()},
                                {"warping", a.warp},
                                {"max_warp_displacement_px", hostsim->max_warp_rad() / px_rad}};
      if (probe && probe->measured()) r["host"]["error"] = probe->summary();
    }
    write_text_atomic(a.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace

Runner add_gtkw_command(CLI::App& app) {
  auto vcd = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("gtkw", "Write a grouped GTKWave save file for a VCD written by arpsim");
  cmd->add_option("vcd", *vcd, "The waveform (.vcd)")->required();
  cmd->add_option("--out,-o", *out, "Save file to write (default: the VCD's name with .gtkw)");
  return [vcd, out] {
    const std::string target = out->empty() ? fs::path(*vcd).replace_extension(".gtkw").string() : *out;
    write_text_atomic(target, gtkw_for_vcd(*vcd, fs::path(*vcd).filename().string()));
    std::printf("arpsim gtkw: %s (open: gtkwave %s %s)\n", target.c_str(), vcd->c_str(), target.c_str());
    return 0;
  };
}

Runner add_run_command(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Run head motion through the pipeline at a chosen fidelity level, frame by frame");
  a->cfg.add_to(*cmd);
  a->cubemap.add_to(*cmd);
  cmd->add_option("--fidelity", a->fidelity,
                  "functional (untimed), lt (loosely timed, scanline quantum), cycle (fast cycle-accurate), "
                  "rtl (detailed cycle-accurate, one SystemC module per stage)")
      ->capture_default_str();
  cmd->add_option("--trace", a->trace, "Trace file (CSV, docs/tracker.md); e.g. from arpsim tracker synth");
  cmd->add_option("--live", a->live,
                  "Live head motion: usb (the first Oculus Rift DK1/DK2), fed to the pipeline frame by frame as it arrives, "
                  "at the display's pace (functional level)");
  a->motion.add_to(*cmd, false);
  cmd->add_option("--frames", a->frames, "Number of frames")->capture_default_str();
  cmd->add_option("--first-frame", a->first, "Index of the first frame (sets its time)")->capture_default_str();
  cmd->add_option("--out-dir", a->out_dir, "Folder for frame_NNNNNN.png (created if missing)")->capture_default_str();
  cmd->add_option("--every", a->every, "Write every Nth frame as an image (0: none)")->capture_default_str();
  cmd->add_flag("--photon-times", a->photon_times, "Also write photon_NNNNNN.csv (every pixel's photon time) with each image");
  cmd->add_option("--threads", a->threads, "Worker threads of the functional level (0: all cores)")->check(CLI::Range(0, 256));
  cmd->add_option("--report", a->report, "JSON report: latencies, stage and FIFO statistics, underflows, speed");
  cmd->add_option("--csv", a->csv, "CSV, one row per frame: underflows, latency, fingerprints");
  cmd->add_option("--vcd", a->vcd, "VCD waveform (lt, cycle, rtl); a bare name goes into waveforms/; a .gtkw is written beside it");
  cmd->add_option("--vcd-lines", a->vcd_lines, "Trace only scanlines START:END counted from the first frame's start");
  cmd->add_option("--vcd-time-us", a->vcd_time_us, "Trace only START:END microseconds of absolute simulated time");
  cmd->add_option("--walk", a->walk, "With --scene: walk through it, 'gallery' (the built-in walk) or a walk file (docs/host.md); "
                  "the host renders by priority between frames (functional level)");
  cmd->add_option("--speed", a->walk_speed, "Walking speed, m/s (default 1, or the walk file's)");
  cmd->add_option("--error-every", a->error_every,
                  "With --walk: measure every Nth frame's error against the truth (PSNR, tracked points; 0: never)")
      ->capture_default_str();
  cmd->add_option("--host-csv", a->host_csv, "With --walk: CSV, one row per display memory (rates, load); needs --report");
  cmd->add_option("--regions", a->region_size,
                  "With --walk: region priority rendering with square columns of this size, metres (0: object-level)")
      ->capture_default_str();
  cmd->add_option("--margin", a->margin, "--regions: how far into a new region before regions are re-assigned, metres")
      ->capture_default_str();
  cmd->add_flag("--region-cubes", a->region_cubes, "--regions: cubes instead of columns, for tall worlds (objects are also cut along horizontal planes)");
  cmd->add_flag("--no-segmentation", a->no_segmentation, "--regions: do not cut large objects along region boundaries");
  cmd->add_flag("--warp", a->warp, "--regions: warp the regions' edges toward slower neighbours (hides tearing)");
  cmd->add_option("--tear-image", a->tear_image,
                  "--regions: write a magnified view (8x) of the 48x32 window with the most crack pixels: displayed | truth | "
                  "cracks magenta, tears yellow, seams cyan");
  cmd->add_option("--tear-at", a->tear_at, "--tear-image: show this place instead, FRAME:EYE:X:Y (e.g. the same place in another run)");
  cmd->add_option("--warp-falloff", a->warp_falloff, "--warp: distance inside a region over which the warp fades, metres (0: half a region)");
  cmd->add_flag("--baseline", a->baseline, "Host baseline: everything in memory 0, rendered every frame");
  cmd->add_option("--threshold-deg", a->threshold_deg, "Priority rendering's threshold angle theta_t (0: one display-memory texel)")
      ->capture_default_str();
  cmd->add_option("--engine-triangles", a->engine.triangles_per_s, "Simulated renderer: triangles per second")->capture_default_str();
  cmd->add_option("--engine-fill", a->engine.pixels_per_s, "Simulated renderer: texels filled per second")->capture_default_str();
  cmd->add_option("--engine-setup", a->engine.object_setup_s, "Simulated renderer: set-up per object, seconds")->capture_default_str();
  cmd->add_option("--stall", a->stalls,
                  "Inject a stall, STAGE:CLOCK:CYCLES (clock counted from the first frame's first pixel); repeatable")
      ->take_all();
  cmd->add_flag("--no-speculation", a->no_speculation,
                "cycle level: compute every pixel stage by stage (no frame speculation; same results, slower)");
  cmd->add_flag("--quiet,-q", a->quiet, "No progress line");
  return [a] { return run(*a); };
}

}  // namespace arp::app
