#include "Session.hpp"

#include "BankRenderer.hpp"
#include "ConfigFile.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

#include "FrameImage.hpp"
#include "HardwareCost.hpp"
#include "HeadMotion.hpp"
#include "PoseConversion.hpp"
#include "TruthProbe.hpp"
#include "common/AtomicFile.hpp"
#include "common/GtkwSaveFile.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"
#include "common/ParameterJson.hpp"
#include "common/PrintfText.hpp"
#include "common/Units.hpp"
#include "common/WholeNumber.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "host/scene/Gallery.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::sim {

namespace {

// a + b (b >= 0) held at the largest time: windows near the end of the
// 64-bit picosecond range (a run may end within a frame of it) never wrap.
int64_t plus_saturated(int64_t a, int64_t b) { return a > INT64_MAX - b ? INT64_MAX : a + b; }

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The files a run writes into --out-dir, named in this one place: frame n's image and its photon times.
struct OutDirFile {
  const char* what;  // for a message
  const char* prefix;
  const char* extension;
  std::string name(int64_t frame) const {
    char n[64];
    std::snprintf(n, sizeof n, "%s%06" PRId64 "%s", prefix, frame, extension);
    return n;
  }
};
constexpr OutDirFile kFrameImage{"image", "frame_", ".png"}, kPhotonTimes{"photon times", "photon_", ".csv"};

// An input or an output the run would overwrite with a file it writes into
// --out-dir, or an output that is that folder: refused before any work. The
// frames written are first + k for k = 0, every, 2 every, ... below `frames`.
void check_out_dir_files(const OutputSpec& o, int64_t first, int64_t frames, const std::vector<NamedPath>& outputs,
                         const std::vector<NamedPath>& inputs) {
  if (o.every <= 0) return;
  for (const NamedPath& f : outputs)
    if (!f.path.empty() && same_folder(f.path, o.out_dir))
      throw InputError(f.option, f.path, "is the --out-dir folder the frames are written into");
  std::vector<NamedPath> files = outputs;
  files.insert(files.end(), inputs.begin(), inputs.end());
  arp::check_out_dir_files("--out-dir", o.out_dir, files, [&](const std::string& name) -> std::string {
    for (const OutDirFile* kind : {&kFrameImage, &kPhotonTimes}) {
      if (kind == &kPhotonTimes && !o.photon_times) continue;
      const std::string prefix = kind->prefix;
      if (name.rfind(prefix, 0) != 0) continue;
      int64_t n = 0;
      const char* digits = name.c_str() + prefix.size();
      const auto [end, ec] = std::from_chars(digits, name.c_str() + name.size(), n);
      if (ec != std::errc() || end == digits || kind->name(n) != name) continue;
      if (n >= first && n - first < frames && (n - first) % o.every == 0) return "frame " + std::to_string(n) + "'s " + kind->what;
    }
    return "";
  });
}

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

// The VCD's final path: ".vcd" added; a bare name goes into waveforms/ (made by build_outputs).
std::string vcd_path(const std::string& arg) {
  fs::path p(arg);
  // "W/", "W/." or "..": a folder, where the name below would make a hidden "W/.vcd".
  if (const fs::path f = p.filename(); f.empty() || f == "." || f == "..")
    throw InputError("--vcd", arg, "is a folder, not a file: name the waveform (W/run writes W/run.vcd)");
  if (!p.has_parent_path()) p = fs::path("waveforms") / p;
  if (p.extension() != ".vcd") p += ".vcd";
  return p.string();
}

// "detailed level in frames 99..101, 199..201 (6 of 600 frames, 1 warm-up frame before each window); functional between".
std::string detail_text(const stage::FrameWindows& w, const RunSpec& s, const scm::TimedResult& res) {
  if (w.windows().empty()) return "  detailed level in no frame (--detail auto found none): functional throughout";
  std::string t = "  detailed level in frames ";
  for (const auto& [f0, f1] : w.windows()) t += (t.back() == ' ' ? "" : ", ") + std::to_string(f0) + ".." + std::to_string(f1 - 1);
  return t + " (" + std::to_string(res.frames - res.untimed_frames) + " of " + std::to_string(res.frames) + " frames, " +
         "each window opened by up to " + std::to_string(s.detail_warmup) + " warm-up frame" + (s.detail_warmup == 1 ? "" : "s") +
         ", fewer at the run's start), functional between";
}

// The host's options act on the simulation of its rendering along a walk (and on its regions): given
// without one they changed nothing, silently.
void check_host_options_used(const HostSpec& h, double regions) {
  for (const auto& [option, given] : {std::pair{"--speed", h.walk_speed.has_value()}, {"--threshold-deg", h.threshold_deg.has_value()},
                                      {"--baseline", h.baseline}, {"--engine-triangles", h.engine_triangles.has_value()},
                                      {"--engine-fill", h.engine_fill.has_value()}, {"--engine-setup", h.engine_setup.has_value()},
                                      {"--regions", h.region_size.has_value()}, {"--margin", h.margin.has_value()},
                                      {"--no-segmentation", !h.segmentation}, {"--region-cubes", h.region_cubes}, {"--warp", h.warp},
                                      {"--warp-falloff", h.warp_falloff.has_value()}})
    if (given && h.walk.empty()) throw InputError(option, "", "acts on the host's rendering along a walk: it needs --walk");
  for (const auto& [option, given] : {std::pair{"--margin", h.margin.has_value()}, {"--no-segmentation", !h.segmentation}})
    if (given && regions == 0) throw InputError(option, "", "needs --regions SIZE (or memory.region_size_m)");
  if (h.warp_falloff && !h.warp) throw InputError("--warp-falloff", "", "needs --warp");
}

void check_spec(const RunSpec& s, scm::Fidelity fid) {
  const auto& o = s.out;
  const auto& h = s.host;
  if (s.frames < 1 || s.frames > 1'000'000) throw InputError("--frames", "", "must be 1 .. 1000000");
  if (o.every < 0) throw InputError("--every", "", "must be >= 0 (0: no images)");
  if (o.error_every < 0) throw InputError("--error-every", std::to_string(o.error_every), "must be >= 0 (0: never)");
  HeadMotion{s.motion, s.trace, nullptr}.check();
  if (!s.live.empty()) {
    if (s.live != "usb") throw InputError("--live", s.live, "the live source is usb (an Oculus Rift DK1/DK2)");
    if (!s.trace.empty() || s.motion.given() || !h.walk.empty())
      throw InputError("--live", "", "live input replaces --trace, --motion and --walk");
    if (fid != scm::Fidelity::Functional)
      throw InputError("--live", "", "live input drives the functional level (the timed levels read their orientation trace ahead)");
  }
  if (!o.host_csv.empty() && (o.report.empty() || h.walk.empty())) throw InputError("--host-csv", "", "needs --walk and --report");
  if (!o.vcd.empty() && (fid == scm::Fidelity::Functional || fid == scm::Fidelity::Verilated))
    throw InputError("--vcd", "", "the " + scm::to_string(fid) +
                                      " level is untimed and has no waveform; use --fidelity lt, cycle or detailed");
  if ((!o.vcd_lines.empty() || !o.vcd_time_us.empty()) && o.vcd.empty())
    throw InputError(o.vcd_lines.empty() ? "--vcd-time-us" : "--vcd-lines", "", "needs --vcd");
  if (o.vcd_signals != "all" && o.vcd_signals != "control") throw InputError("--vcd-signals", o.vcd_signals, "must be all or control");
  if (!s.clock_gating && fid != scm::Fidelity::Detailed && fid != scm::Fidelity::Cycle)
    throw InputError("--no-clock-gating", "", "only the cycle-accurate levels (cycle, detailed) have clocks to gate");
  if (!s.speculate && fid != scm::Fidelity::Cycle)
    throw InputError("--no-speculation", "", "only the cycle level speculates (the detailed level never does): it would change nothing");
  if (o.vcd_signals != "all" && o.vcd.empty()) throw InputError("--vcd-signals", o.vcd_signals, "needs --vcd");
  if (o.truth_face_size != 0 && (o.error_every <= 0 || h.walk.empty()))
    throw InputError("--truth-face-size", std::to_string(o.truth_face_size),
                     "needs --walk and --error-every > 0 (it sizes the truth the error is measured against)");
  if (o.truth_supersample != 1 && (o.error_every <= 0 || h.walk.empty()))
    throw InputError("--truth-supersample", std::to_string(o.truth_supersample),
                     "needs --walk and --error-every > 0 (it samples the truth the error is measured against)");
  if (o.truth_supersample < 1 || o.truth_supersample > 4)
    throw InputError("--truth-supersample", std::to_string(o.truth_supersample), "must be 1 .. 4 samples a pixel across");
  if (o.truth_supersample > 1 && s.config.timing.fields_per_frame != 1)
    throw InputError("--truth-supersample", std::to_string(o.truth_supersample),
                     "needs a progressive display (display.fields_per_frame 1): an interlaced one would take a pixel's "
                     "rows of samples in different fields");
  if (o.truth_supersample > 1)  // the truth's display at N x, within every key's range, before anything runs
    config::check(truth_image_config(s.config, o.truth_supersample),
                  "--truth-supersample " + std::to_string(o.truth_supersample) + " (the truth at " +
                      std::to_string(o.truth_supersample) + " x the display's resolution)");
  if (o.truth_face_size != 0) {  // its range (the key's) before what it would cost
    dp::ArpConfig t = s.config;
    set_parameter(*dp::arp_parameters().find("memory.face_size"), nlohmann::json(o.truth_face_size), "--truth-face-size", t);
  }
  const double regions = s.config.memory.region_size_m;  // (--regions already applied: the constructor)
  check_host_options_used(h, regions);
  if (!h.walk.empty() && !s.memories.position.empty()) throw InputError("--position", "", "the walk moves the head: give one or the other");
  if (!h.walk.empty() && s.memories.time_s)
    throw InputError("--time", "", "a walk's scene time is the run's own (each frame's): --time is for a still scene");
  if (!o.tear_image.empty() && (regions == 0 || o.error_every <= 0 || h.walk.empty()))
    throw InputError("--tear-image", "", "needs --walk, --regions and --error-every > 0 (tearing is measured against the truth)");
  if (h.region_cubes && regions == 0) throw InputError("--region-cubes", "", "needs --regions SIZE (or memory.region_size_m)");
  if (!o.tear_at.empty() && o.tear_image.empty()) throw InputError("--tear-at", "", "needs --tear-image");
  host::check_image_output("--tear-image", o.tear_image);
  if (h.warp && regions == 0) throw InputError("--warp", "", "region warping needs --regions (or memory.region_size_m)");
  check_renderer(s.memories, s.config.memory.depth_bits);
  s.memories.checked_ipd_m();  // (with a walk it was checked once the scene was loaded)
  check_model_fits_memory(s.config, s.config_source, !s.memories.scene.empty(),
                          !s.memories.scene.empty() && !h.walk.empty() && o.error_every > 0 ? std::max(o.truth_face_size, 0) : -1);
  if (h.warp && s.memories.renderer != "software")
    throw InputError("--renderer", s.memories.renderer, "region warping (--warp) moves vertices on the CPU: it needs --renderer software");
  if (o.every > 0 || o.photon_times) check_output_folder("--out-dir", o.out_dir);
  const std::vector<NamedPath> outputs = {
      {"--report", o.report}, {"--csv", o.csv}, {"--host-csv", o.host_csv}, {"--tear-image", o.tear_image},
      {"--record-live", s.record_live},
      {"--vcd", o.vcd.empty() ? "" : vcd_path(o.vcd), true},
      {"--vcd's save file", o.vcd.empty() ? "" : fs::path(vcd_path(o.vcd)).replace_extension(".gtkw").string(), true}};
  std::vector<NamedPath> inputs = {{"--config", s.config_source}, {"--trace", s.trace}, {"--walk", h.walk == "gallery" ? "" : h.walk}};
  for (NamedPath& f : s.memories.input_files()) inputs.push_back(std::move(f));
  check_output_paths(outputs, inputs);
  const bool untimed = fid == scm::Fidelity::Functional || fid == scm::Fidelity::Verilated;
  const auto issues = untimed ? dp::validate(s.config) : dp::validate_timed(s.config);
  if (!issues.empty()) throw InputError(s.config_source, issues.front().key, issues.front().reason);
  // After the configuration's check: the limit depends on its clock.
  if (const std::string why = dp::VideoTiming(s.config.timing).frames_out_of_range(s.first_frame, s.frames); !why.empty())
    throw InputError("--first-frame", "", why);
  check_out_dir_files(o, s.first_frame, s.frames, outputs, inputs);  // (frames in range: n - first cannot overflow)
  if (!o.tear_at.empty()) parse_tear_at(o.tear_at, s.first_frame, s.frames, o.error_every, s.config.timing);  // before any work
}

}  // namespace

Session::Session(RunSpec spec)
    : spec_(std::move(spec)),
      timing_(spec_.config.timing),
      stream_(dp::OrientationStream::constant(dp::Quat{})),
      memories_(spec_.config.memory, spec_.config.timing.eyes) {
  // --threshold-deg and --engine-* override the configuration's keys: the report's configuration says what ran.
  if (const auto& t = spec_.host.threshold_deg) {
    HostSpec::threshold_rad(*t);  // its range, named as the option
    spec_.config.memory.threshold_deg = *t;
  }
  for (const auto& [option, key, value] : {std::tuple{"--engine-triangles", "host.triangles_per_s", spec_.host.engine_triangles},
                                           std::tuple{"--engine-fill", "host.texels_per_s", spec_.host.engine_fill},
                                           std::tuple{"--engine-setup", "host.object_setup_s", spec_.host.engine_setup},
                                           std::tuple{"--regions", "memory.region_size_m", spec_.host.region_size},
                                           std::tuple{"--margin", "memory.region_margin_m", spec_.host.margin}})
    if (value) set_parameter(*dp::arp_parameters().find(key), nlohmann::json(*value), option, spec_.config);  // its declared range
  spec_.memories.expect_plan(spec_.config, spec_.config_source);
  if (!scm::parse(spec_.fidelity, fidelity_))
    throw InputError("--fidelity", spec_.fidelity, "must be functional, lt, cycle, detailed (rtl) or verilated");
  build_detail_windows();
  check_spec(spec_, fidelity_);
  start_ps_ = timing_.cycles_to_ps(timing_.frame_start_cycle(spec_.first_frame));
  end_ps_ = timing_.cycles_to_ps(timing_.frame_start_cycle(spec_.first_frame + spec_.frames));
  timed_end_ps_ = timing_.cycles_to_ps(dp::PipelineSchedule(spec_.config).run_end_cycle(spec_.first_frame + spec_.frames));
  stalls_ = stall_windows();  // (a bad window was refused only after the memories were filled: 0.7 s)
  vcd_window_ = vcd_option_window();
  build_motion();
  build_memories();
}

Session::~Session() = default;

// --detail: the run is functional except in these windows of frames, which
// the detailed level simulates, each with --detail-warmup detailed frames
// before it (what the pipeline's registers hold when the window starts).
// `auto` adds its windows once the motion is known (add_auto_detail).
void Session::build_detail_windows() {
  if (std::find(spec_.detail.begin(), spec_.detail.end(), "auto") == spec_.detail.end() &&
      spec_.detail_speed_dps != RunSpec{}.detail_speed_dps)
    throw InputError("--detail-speed-dps", "", "needs --detail auto");
  if (spec_.detail.empty()) {
    if (spec_.detail_warmup != 1) throw InputError("--detail-warmup", "", "needs --detail");
    return;
  }
  if (fidelity_ != scm::Fidelity::Functional && fidelity_ != scm::Fidelity::Detailed)
    throw InputError("--detail", "", "switches between the functional and the detailed level: leave --fidelity at functional (or detailed)");
  if (spec_.detail_warmup < 0 || spec_.detail_warmup > 1000) throw InputError("--detail-warmup", "", "must be 0 .. 1000 frames");
  if (!(spec_.detail_speed_dps >= 0 && spec_.detail_speed_dps <= 1e6))
    throw InputError("--detail-speed-dps", "", "must be 0 .. 1000000 degrees per second");
  for (const std::string& d : spec_.detail) {
    if (d == "auto") {
      auto_detail_ = true;
      continue;
    }
    const auto colon = d.find(':');
    const std::optional<int64_t> a = whole_number(std::string_view(d).substr(0, colon));
    const std::optional<int64_t> b = colon == std::string::npos ? a : whole_number(std::string_view(d).substr(colon + 1));
    if (!a || !b)
      throw InputError("--detail", d, "expected START:END (frames counted from the first frame, END exclusive), one frame, or auto");
    // (one frame: its end is the next, compared without adding one -- a frame at the top of int64 wrapped)
    if (*a < 0 || *a >= spec_.frames || (colon != std::string::npos && (*b <= *a || *b > spec_.frames)))
      throw InputError("--detail", d, "frames must satisfy 0 <= START < END <= --frames (" + std::to_string(spec_.frames) + ")");
    detail_windows_.push_back({*a, colon == std::string::npos ? *a + 1 : *b});
  }
  fidelity_ = scm::Fidelity::Detailed;
}

// `--detail auto`: the frames where the head turns faster than
// --detail-speed-dps (its mean speed over the frame, from the run's motion)
// and the frames an injected stall (--stall) reaches, then the windows given
// by hand; with the warm-up frames before each, as absolute frames.
void Session::add_auto_detail() {
  if (spec_.detail.empty()) return;
  std::vector<stage::FrameWindows::Window> w = detail_windows_;
  if (auto_detail_) {
    const std::vector<double> v = frame_speeds_dps();
    for (int64_t k = 0; k < spec_.frames; ++k)
      if (v[static_cast<size_t>(k)] > spec_.detail_speed_dps) {
        w.push_back({k, k + 1});
        ++auto_fast_frames_;
      }
    std::set<int64_t> stalled;
    for (const stage::StallWindow& st : stalls_)
      for (auto [k, end] = stall_frames(st); k < end; ++k) stalled.insert(k);
    for (const int64_t k : stalled) w.push_back({k, k + 1});
    auto_stall_frames_ = static_cast<int64_t>(stalled.size());
  }
  for (auto& [a, b] : w) {
    a = spec_.first_frame + std::max<int64_t>(0, a - spec_.detail_warmup);
    b = spec_.first_frame + b;
  }
  timed_frames_ = stage::FrameWindows(std::move(w));
  if (timed_frames_.windows().empty() && !spec_.out.vcd.empty())
    throw InputError("--vcd", spec_.out.vcd, "--detail auto found no frame to detail (no head speed over --detail-speed-dps, no --stall): "
                                             "no detailed clock to trace; name a window (--detail START:END) or leave --vcd out");
  // A stall reaching a functional frame would stall nothing there, or lose what it pushed into it: said, not ignored.
  for (size_t i = 0; i < stalls_.size(); ++i) {
    const auto [k0, k1] = stall_frames(stalls_[i]);
    for (int64_t k = k0; k < k1; ++k)
      if (!timed_frames_.contains(spec_.first_frame + k))
        throw InputError("--stall", spec_.stalls[i],
                         "reaches frames " + std::to_string(k0) + ".." + std::to_string(k1 - 1) + ", and --detail leaves frame " +
                             std::to_string(k) + " at the functional level, where nothing stalls: add --detail " +
                             std::to_string(k0) + ":" + std::to_string(std::min(k1, spec_.frames)) +
                             (auto_detail_ ? std::string() : std::string(" or use --detail auto")));
  }
}

// The frames a stall reaches, [first, end) counted from the run's first: it holds the pipeline from its
// clock on, and what it pushed back drains by the end of the frame after the one it ends in.
std::pair<int64_t, int64_t> Session::stall_frames(const stage::StallWindow& st) const {
  const int64_t base = timing_.frame_start_cycle(spec_.first_frame), F = timing_.frame_cycles();
  const int64_t first = (st.first_cycle - base) / F;
  return {first, std::min(spec_.frames, (st.first_cycle + st.cycles - base) / F + 2)};
}

// The head motion: a trace, synthetic motion, a walk (facing where it goes,
// turning on top of it), or live input that grows frame by frame. Generated
// motion (synthetic, or the still head of a walk) is not held for the whole
// run: the stream is extended a window ahead before each frame and trimmed
// behind it (extend_motion), so memory does not grow with the run's length.
host::WalkPath HostSpec::make_walk() const {
  if (walk_speed && !(*walk_speed >= 0 && *walk_speed <= 1000))
    throw InputError("--speed", "", "must be 0 .. 1000 m/s (0: standing at the walk's first point)");
  if (walk == "gallery") return host::WalkPath(host::gallery_walk(), walk_speed.value_or(1.0), "gallery walk");
  host::WalkPath w = host::load_walk_file(walk);
  if (walk_speed) w = host::WalkPath(w.points(), *walk_speed, walk);
  return w;
}

// A configuration planned for one motion (plan.motion_hash: the walk, and the
// head's own motion on it) run over another: said once, before the run. A run without a scene shows a cube map,
// which the plan's walk has nothing to do with.
void Session::warn_if_planned_for_another_motion() const {
  const int64_t planned = spec_.config.plan.motion_hash;
  if (planned == 0 || spec_.memories.scene.empty()) return;
  const std::string& cfg = spec_.config_source;
  if (!walk_) {
    std::fprintf(stderr, "arpsim: warning: %s was planned for a walk (plan.motion_hash %lld); this run's head stays in one "
                         "place (no --walk): its memories were sized for the walk's motion%s (`arpsim plan --speed 0` "
                         "plans for standing at the walk's first point)\n",
                 cfg.c_str(), static_cast<long long>(planned), spec_.config.memory.tiles.empty() ? "" : ", and its tiles for where the walk draws");
    return;
  }
  // A plan's tiles are bounded for its walk: another motion (a slower one puts objects in slower memories) draws outside them.
  const char* tiles = spec_.config.memory.tiles.empty() ? "" : " (its memory.tiles hold only the tiles that walk draws on: texels drawn outside them are lost)";
  // (A live head's motion is not known before the run: the walk alone is compared.)
  const HeadMotion head{spec_.motion, spec_.trace, nullptr};
  if (const int64_t h = motion_hash(*walk_, head); h != planned)
    std::fprintf(stderr, "arpsim: warning: %s was planned for another motion (plan.motion_hash %lld)%s; walk %s at %g m/s%s "
                         "hashes to %lld: run `arpsim plan` for it (with the same --motion or --trace)\n",
                 cfg.c_str(), static_cast<long long>(planned), tiles, spec_.host.walk.c_str(), walk_->speed(),
                 head.given() ? (", the head turning with " + head.describe()).c_str() : "", static_cast<long long>(h));
}

// memory.assignment against the scene: a name no object has is an error in a configuration written for this
// scene (or for none), and a warning where the plan was made for another (said once, as the scene is); by
// regions or the baseline the assignment is not used, which is said once too.
void Session::check_assignment() const {
  const dp::MemoryConfig& m = spec_.config.memory;
  if (m.assignment.empty()) return;
  const std::string where = spec_.config_source + ": memory.assignment";
  if (spec_.host.baseline || regions_) {
    std::fprintf(stderr, "arpsim: warning: %s is not used: %s places every object itself\n", where.c_str(),
                 spec_.host.baseline ? "the baseline" : "region priority rendering");
    return;
  }
  check_assignment_names(host_->scheduler().unknown_names(), *scene_, spec_.config.plan.scene_hash, spec_.config_source);
}

double HostSpec::threshold_rad(double deg) {
  if (!(deg >= 0) || deg > 90) throw InputError("--threshold-deg", "", "must be 0 .. 90 degrees (0: one texel)");
  // (a positive angle that rounds to no radian would read as 0, one texel, silently)
  if (deg > 0 && deg < 1e-9) throw InputError("--threshold-deg", printf_text("%g", deg), "must be 0 (one texel) or at least 1e-9 degrees");
  return deg_to_rad(deg);
}

// A trace is read over the run's window only and held.
void Session::build_motion() {
  const HostSpec& h = spec_.host;
  if (!h.walk.empty()) {
    if (spec_.memories.scene.empty()) throw InputError("--walk", "", "needs --scene (what to walk through)");
    walk_ = std::make_unique<host::WalkPath>(h.make_walk());
  }
  if (!spec_.trace.empty()) {
    // Only what the run can latch: a second of margin before the first frame covers every lead.
    std::vector<tracker::PoseSample> poses =
        tracker::read_trace_csv(spec_.trace, {start_ps_ - kPsPerSecond, plus_saturated(end_ps_, kPsPerSecond / 100)});
    motion_source_ = spec_.trace;
    // A trace that begins after the run does: its first sample stands for the motion before it (sample-and-hold
    // backwards), which no tracker gave -- said, not refused (a run may start early on purpose).
    if (poses.front().time_ps > start_ps_)
      motion_notes_.push_back("warning: the trace starts at " + printf_text("%.6f", ps_to_seconds(poses.front().time_ps)) +
                              " s, after the run's first frame at " + printf_text("%.6f", ps_to_seconds(start_ps_)) +
                              " s: the pixels before it show its first sample");
    // Told before the run: what the window of the trace looks like, and what a human head would not do.
    trace_summary_ = tracker::summarize_motion(poses);
    const auto d = tracker::describe(*trace_summary_);
    motion_notes_.push_back("trace " + spec_.trace + " over the run's window: " + d[0]);
    motion_notes_.push_back("  " + d[1]);
    for (const auto& w : tracker::motion_warnings(*trace_summary_)) motion_notes_.push_back("warning: " + w);
    trace_poses_ = std::make_shared<std::vector<tracker::PoseSample>>(std::move(poses));
  } else if (spec_.motion.given()) {
    // Synthetic motion keeps its sample times in double seconds; past the pose time limit it refuses to start.
    if (ps_to_seconds(start_ps_) - 1.0 > tracker::kPoseTimeLimitS)
      throw InputError("--first-frame", std::to_string(spec_.first_frame),
                       "starts " + std::to_string(static_cast<int64_t>(ps_to_seconds(start_ps_))) +
                           " s in; synthetic motion (--motion) covers the first " + tracker::pose_time_limit_text() +
                           ": use a trace or a still head");
    motion_source_ = "synthetic " + spec_.motion.motion;
  }
  warn_if_planned_for_another_motion();  // (after the trace is read: a trace that does not parse is said alone)
  add_auto_detail();  // from the motion afresh: before extend_motion hands a trace's poses to the run
  more_poses_ = pose_source(true);
  if (walk_) motion_source_ = (h.walk == "gallery" ? std::string("gallery walk") : h.walk) + " with " + motion_source_;
  check_record_live(spec_.record_live, !spec_.live.empty());
  if ((live_ = tracker::live_source(spec_.live, spec_.tracker))) motion_source_ = "live " + live_->describe();
  // Opened before any work: an unwritable path is said now, not after the run.
  if (live_) live_intake_ = std::make_unique<LiveIntake>(*live_, spec_.record_live);
  // Live input appends to the stream as it arrives: generated motion is then made whole first.
  const int64_t frame_ps = timing_.cycles_to_ps(timing_.frame_start_cycle(spec_.first_frame + 1)) - start_ps_;
  extend_motion(live_ ? INT64_MAX : plus_saturated(start_ps_, 3 * frame_ps + kPsPerSecond));
}

// The run's generated motion from its start, afresh: appends the poses
// through a time (and one past it) and says whether it has given all. A
// trace's poses are handed over (`consume`: moved, once) or copied. Empty for
// a still head without a walk, and for live input.
Session::MorePoses Session::pose_source(bool consume) const {
  if (trace_poses_) {
    if (consume)
      return [p = trace_poses_](int64_t, std::vector<tracker::PoseSample>& out) {
        out = std::move(*p);
        p->clear();
        return true;
      };
    return [p = trace_poses_](int64_t, std::vector<tracker::PoseSample>& out) {
      out = *p;
      return true;
    };
  }
  if (spec_.motion.given()) {
    // A second of margin before the first frame covers every lead; 10 ms after the last covers the sampling.
    auto g = std::make_shared<tracker::MotionGenerator>(
        spec_.motion.generator(ps_to_seconds(start_ps_) - 1.0, ps_to_seconds(end_ps_ - start_ps_) + 1.01));
    return [g](int64_t through_ps, std::vector<tracker::PoseSample>& out) {
      g->take_through(through_ps, out);
      return g->done();
    };
  }
  if (!walk_) return {};
  // A still head on the walk: sampled at 1 kHz (the walk turns it, face_walk).
  const double t1 = ps_to_seconds(end_ps_) + 0.01;
  return [tt = ps_to_seconds(start_ps_) - 1.0, t1](int64_t through_ps, std::vector<tracker::PoseSample>& out) mutable {
    for (; tt <= t1; tt += 1e-3) {
      tracker::PoseSample p;
      p.time_ps = seconds_to_ps(tt);
      out.push_back(p);
      if (p.time_ps > through_ps) {
        tt += 1e-3;
        return false;
      }
    }
    return true;
  };
}

// On a walk the head faces where it goes, turning on top of that.
void Session::face_walk(std::vector<tracker::PoseSample>& poses) const {
  if (walk_) sim::face_walk(*walk_, poses);
}

// The head's mean angular speed over each frame of the run, degrees per
// second (the rotation from the sample at its start to the one at its end),
// from the run's motion generated afresh: a second of it held at a time.
std::vector<double> Session::frame_speeds_dps() const {
  std::vector<double> out(static_cast<size_t>(spec_.frames), 0.0);
  MorePoses src = pose_source(false);
  if (!src) return out;
  std::deque<tracker::PoseSample> held;
  bool done = false;
  auto at = [&held](int64_t t) {  // the last sample at or before t (or the first)
    auto it = std::upper_bound(held.begin(), held.end(), t, [](int64_t v, const tracker::PoseSample& p) { return v < p.time_ps; });
    return glm::normalize((it == held.begin() ? *it : *std::prev(it)).orientation);
  };
  for (int64_t k = 0; k < spec_.frames; ++k) {
    const int64_t f0 = timing_.cycles_to_ps(timing_.frame_start_cycle(spec_.first_frame + k));
    const int64_t f1 = timing_.cycles_to_ps(timing_.frame_start_cycle(spec_.first_frame + k + 1));
    while (!done && (held.empty() || held.back().time_ps < f1)) {
      std::vector<tracker::PoseSample> more;
      done = src(plus_saturated(f1, kPsPerSecond), more);
      face_walk(more);
      held.insert(held.end(), more.begin(), more.end());
    }
    if (held.empty()) return out;
    const double c = std::min(1.0, std::abs(glm::dot(at(f0), at(f1))));
    out[static_cast<size_t>(k)] = rad_to_deg(2.0 * std::acos(c)) / ps_to_seconds(f1 - f0);
    while (held.size() > 1 && held[1].time_ps <= f1) held.pop_front();
  }
  return out;
}

// After frame k is scanned out (every level reports its frames in order),
// the window of generated motion moves: through two more frames and a second
// ahead (the next frame's pixels are already in flight at the timed levels),
// and trimmed to a second and two frames behind frame k (every latch lead).
// Live input arrives by itself (build_live_input) and is trimmed the same way:
// held whole, a tracker's 1 kHz grows by 144 MB an hour.
void Session::advance_motion(int64_t frame) {
  if (!live_ && !more_poses_) return;
  const int64_t f0 = timing_.cycles_to_ps(timing_.frame_start_cycle(frame));
  const int64_t f1 = timing_.cycles_to_ps(timing_.frame_start_cycle(frame + 1));
  if (live_) live_held_max_ = std::max(live_held_max_, static_cast<int64_t>(stream_.held()));
  else extend_motion(plus_saturated(f1, 2 * (f1 - f0) + kPsPerSecond));
  if (motion_started_ || live_) stream_.discard_before(f0 - 2 * (f1 - f0) - kPsPerSecond);
}

// Appends the generated motion through `through_ps` (and one sample past it) to the stream.
void Session::extend_motion(int64_t through_ps) {
  if (!more_poses_ || motion_done_) return;
  if (motion_started_ && last_pose_ps_ > through_ps) return;  // already there (the host asks several times a frame)
  std::vector<tracker::PoseSample> more;
  motion_done_ = more_poses_(through_ps, more);
  if (more.empty()) return;
  face_walk(more);
  last_pose_ps_ = more.back().time_ps;
  if (!motion_started_) stream_ = dp::OrientationStream(to_orientation_samples(more), motion_source_);
  else stream_.append(to_orientation_samples(more), motion_source_);
  motion_started_ = true;
}

// The display memories: a host simulating priority rendering over the walk, or a cube map / scene once.
void Session::build_memories() {
  const HostSpec& h = spec_.host;
  const dp::ArpConfig& c = spec_.config;
  if (!walk_) {
    spec_.memories.fill(memories_, stream_[stream_.index_at(start_ps_)].q, memory_source_, spec_.threads);
    return;
  }
  scene_ = std::make_unique<host::Scene>(spec_.memories.load_scene());
  host::PriorityConfig pc = host::PriorityConfig::of(c.memory, timing_.refresh_hz());
  pc.baseline = h.baseline;
  if (h.baseline || c.memory.region_size_m != 0) pc.assignment.clear();  // they place objects themselves (check_assignment says so)
  auto head = [this](double tt) {
    // The host may render ahead of the frame (a memory queued behind a busy
    // engine): the generated motion is extended to whatever time it asks for.
    const int64_t t_ps = seconds_to_ps(tt);
    extend_motion(t_ps);
    const dp::Quat& q = stream_[stream_.index_at(t_ps)].q;
    return glm::dquat(q.w, q.x, q.y, q.z);
  };
  const double region_m = c.memory.region_size_m;  // (--regions overrides it: the constructor)
  const std::string region_source = h.region_size ? "--regions" : spec_.config_source + ": memory.region_size_m";
  if (region_m != 0) {
    // Region priority rendering: the world in columns, large objects cut along them.
    grid_ = std::make_unique<host::RegionGrid>(scene_->extent_min, scene_->extent_max, region_m, h.region_cubes, region_source);
    segmented_ = host::segment_scene(*scene_, *grid_, h.segmentation);
    scene_ = std::make_unique<host::Scene>(std::move(segmented_.scene));
    host::RegionConfig rc;
    rc.region_size_m = region_m;
    rc.margin_m = c.memory.region_margin_m;
    rc.memories = c.memory.count;
    rc.threshold_rad = pc.threshold_rad;
    regions_ = std::make_unique<host::RegionScheduler>(*grid_, rc, c.memory.face_size, walk_->position(ps_to_seconds(start_ps_)),
                                                       h.margin ? std::string("--margin")
                                                       : h.region_size
                                                           ? "--regions, with " + spec_.config_source + "'s memory.region_margin_m"
                                                           : spec_.config_source + ": memory.region_margin_m");
  }
  host_ = std::make_unique<host::HostSimulation>(*scene_, pc, host::RenderEngine(c.host), *walk_, head, memories_, spec_.memories.checked_ipd_m(),
                                                 timing_.refresh_hz());
  check_assignment();
  // A head with no motion of its own only faces the walk: its turn rate from the walk itself, exact at any time
  // (the motion stream holds it at 1 kHz samples), from the run's start on, as the plan replays it. A head
  // motion given (--motion, --trace) was already turning before the run.
  if (!spec_.motion.given() && spec_.trace.empty() && spec_.live.empty())
    host_->use_turn_rate([w = walk_.get(), t0 = ps_to_seconds(start_ps_)](double t, double dt) {
      return host::facing_turn_rate_rad_s(*w, t, dt, t0);
    });
  if (regions_) {
    host_->use_regions(regions_.get(), segmented_.region, segmented_.span);
    const double falloff = h.warp_falloff.value_or(0.0);
    if (!(falloff >= 0) || falloff > region_m) throw InputError("--warp-falloff", "", "must be 0 .. the region size");
    host_->use_warping(h.warp, falloff > 0 ? falloff : region_m / 2);
  }
  if (spec_.memories.renderer != "software")
    host_->use_renderer(make_bank_renderer(spec_.memories.renderer, spec_.threads, spec_.memories.face_culling));
  host_->set_render_threads(spec_.threads);
  host_->set_face_culling(spec_.memories.face_culling);
  host_->prime(ps_to_seconds(start_ps_));
  memory_source_ = "scene " + scene_->name + " (" + std::to_string(scene_->objects.size()) + " objects, " +
                   std::to_string(scene_->triangles()) + " triangles), host rendering " +
                   (h.baseline ? "everything every frame (baseline)" : "by priority") +
                   (spec_.memories.renderer == "software" ? "" : ", " + spec_.memories.renderer + " renderer");
}

// Live: before each frame, take what the device has sent until the frame's
// end on the wall clock (the run goes at the display's pace, or slower: then
// it takes what has arrived), placed on the run's timeline by device time; an
// unplug holds the last pose and the run goes on.
void Session::build_live_input(stage::TimedInputs& in) {
  const auto wall0 = Clock::now();
  live_intake_->start(stream_, start_ps_, motion_source_);
  auto got = std::make_shared<std::vector<tracker::PoseSample>>();
  in.before_frame = [this, wall0, got](int64_t frame, double) {
    const int64_t until_ps = timing_.cycles_to_ps(timing_.frame_start_cycle(frame + 1)) - start_ps_;
    for (;;) {
      const auto wall_ps = static_cast<int64_t>(std::chrono::duration<double>(Clock::now() - wall0).count() * 1e12);
      if (wall_ps >= until_ps) {
        // Behind: the frame ends earlier on the run's timeline than the device's clock has gone.
        live_behind_ps_ = wall_ps - until_ps;
        live_behind_max_ps_ = std::max(live_behind_max_ps_, live_behind_ps_);
        break;
      }
      live_behind_ps_ = 0;
      live_->poll(*got, static_cast<int>(std::min<int64_t>(5, (until_ps - wall_ps) / 1'000'000'000 + 1)));
    }
    // A run slower than the display has no time left here: it still takes everything the device sent
    // (placed by device time, so later frames find it), or the samples would wait in the stream's bound.
    live_->poll(*got, 0);
    for (const auto& e : live_->take_events()) std::fprintf(stderr, "arpsim run: live input %s\n", e.c_str());
    live_intake_->take(stream_, *got, motion_source_);
    got->clear();
  };
}

// "; 2.4 s behind the tracker" once a live run lags by more than a frame, and past the stream's bound
// how many samples it has dropped; empty while it keeps up.
std::string Session::live_lag_text() const {
  const double behind_s = static_cast<double>(live_behind_ps_) * 1e-12;
  if (behind_s * timing_.refresh_hz() < 1.0) return "";
  char b[160];
  tracker::StreamStats st;
  live_->usb_stats(st);
  if (st.dropped_unconsumed > 0)
    std::snprintf(b, sizeof b, "; %.1f s behind the tracker, past the %g s it keeps: %" PRId64 " samples dropped", behind_s,
                  tracker::RiftStreamOptions{}.max_pending_s, st.dropped_unconsumed);
  else
    std::snprintf(b, sizeof b, "; %.1f s behind the tracker (it keeps %g s)", behind_s, tracker::RiftStreamOptions{}.max_pending_s);
  return b;
}

// Every output is checked before anything is simulated: folders made, files writable.
void Session::build_outputs(scm::TimedRunOptions& opt) {
  const OutputSpec& o = spec_.out;
  if (o.every > 0 || o.photon_times) make_output_folder("--out-dir", o.out_dir);
  log_ = std::make_unique<FrameLog>(o.csv, o.report, frame_csv_header());
  if (o.vcd.empty()) return;
  vcd_final_ = vcd_path(o.vcd);
  make_output_folder("--vcd", fs::path(vcd_final_).parent_path().string());
  vcd_tmp_base_ = temp_path_beside(vcd_final_).string();
  opt.vcd.path = vcd_tmp_base_;
  opt.vcd.shown = vcd_final_;
  opt.vcd.data = o.vcd_signals == "all";
  if (vcd_window_) {
    std::tie(opt.vcd.from_ps, opt.vcd.to_ps) = *vcd_window_;
  } else if (!timed_frames_.every_frame()) {
    // With detailed windows: the first window (its warm-up frames too), from the vertical blank before it to the one after it.
    const dp::PipelineSchedule sched(spec_.config);
    const auto [f0, f1] = timed_frames_.windows().front();
    opt.vcd.from_ps = timing_.cycles_to_ps(sched.swap_cycle(f0 - 1));
    opt.vcd.to_ps = timing_.cycles_to_ps(sched.swap_cycle(f1 - 1) + 1);
  }
}

// --vcd-lines or --vcd-time-us as a span of the run's simulated time, ps (none: neither given, or no --vcd).
std::optional<std::pair<int64_t, int64_t>> Session::vcd_option_window() const {
  const OutputSpec& o = spec_.out;
  if (o.vcd.empty()) return std::nullopt;
  if (!o.vcd_lines.empty()) {
    const auto [l0, l1] = parse_window("--vcd-lines", o.vcd_lines);
    if (l0 < 0 || l0 != std::floor(l0) || l1 != std::floor(l1)) throw InputError("--vcd-lines", o.vcd_lines, "lines must be whole numbers >= 0");
    // Within the scan lines the timed levels simulate, compared before any product is formed (a line beyond them
    // traced nothing, or wrapped the cycle count). They end at the last frame's vertical blank: the lines of that
    // blank were accepted and gave an empty waveform.
    const int64_t base = timing_.frame_start_cycle(spec_.first_frame), h = spec_.config.timing.h_total();
    const int64_t lines = (dp::PipelineSchedule(spec_.config).run_end_cycle(spec_.first_frame + spec_.frames) - base) / h;
    if (l1 > static_cast<double>(lines))
      throw InputError("--vcd-lines", o.vcd_lines, "the run simulates " + std::to_string(lines) + " whole scan lines (--frames " +
                                                       std::to_string(spec_.frames) +
                                                       ", up to the last frame's vertical blank): END must be at most that");
    return std::pair{timing_.cycles_to_ps(base + static_cast<int64_t>(l0) * h), timing_.cycles_to_ps(base + static_cast<int64_t>(l1) * h)};
  }
  if (!o.vcd_time_us.empty()) {
    const auto [t0, t1] = parse_window("--vcd-time-us", o.vcd_time_us);
    // Within the run's simulated time, compared before rounding to picoseconds (a window past int64's
    // picoseconds wrapped, and was called shorter than one).
    if (t0 < 0 || t1 * 1e6 > static_cast<double>(timed_end_ps_) || t1 * 1e6 <= static_cast<double>(start_ps_))
      throw InputError("--vcd-time-us", o.vcd_time_us,
                       "the window must lie within the run's simulated time, " + printf_text("%.3f", static_cast<double>(start_ps_) * 1e-6) +
                           " .. " + printf_text("%.3f", static_cast<double>(timed_end_ps_) * 1e-6) +
                           " us (--first-frame, --frames; up to the last frame's vertical blank)");
    const int64_t from_ps = static_cast<int64_t>(std::llround(t0 * 1e6)), to_ps = static_cast<int64_t>(std::llround(t1 * 1e6));
    if (to_ps <= from_ps)
      throw InputError("--vcd-time-us", o.vcd_time_us, "the window is shorter than the simulation's picosecond: nothing to trace");
    return std::pair{from_ps, to_ps};
  }
  return std::nullopt;
}

// --stall STAGE:CLOCK:CYCLES, CLOCK counted from the first frame's first active pixel.
std::vector<stage::StallWindow> Session::stall_windows() const {
  std::vector<stage::StallWindow> out;
  for (const std::string& spec : spec_.stalls) {
    const auto c1 = spec.find(':'), c2 = spec.find(':', c1 == std::string::npos ? 0 : c1 + 1);
    stage::StallWindow w{dp::Stage::Lens, 0, 0};
    bool ok = c1 != std::string::npos && c2 != std::string::npos;
    if (ok) {
      const std::string name = spec.substr(0, c1);
      ok = false;
      for (int k = 0; k + 1 < dp::kStageCount; ++k)
        if (name == dp::stage_key(static_cast<dp::Stage>(k))) {
          w.stage = static_cast<dp::Stage>(k);
          ok = true;
        }
      const std::optional<int64_t> clock = whole_number(std::string_view(spec).substr(c1 + 1, c2 - c1 - 1));
      const std::optional<int64_t> cycles = whole_number(std::string_view(spec).substr(c2 + 1));
      ok = ok && clock && cycles && *cycles > 0 && *cycles <= 1'000'000'000;
      if (ok) {
        // Within the run (a stall past its end stalled nothing, silently; one before its start is no clock of it).
        const int64_t run_clocks = timing_.frame_start_cycle(spec_.first_frame + spec_.frames) - timing_.frame_start_cycle(spec_.first_frame);
        if (*clock < 0 || *clock >= run_clocks)
          throw InputError("--stall", spec, "CLOCK must be a pixel clock of the run, 0 .. " + std::to_string(run_clocks - 1) +
                                                " (counted from the first frame's start; --frames " + std::to_string(spec_.frames) + ")");
        w.first_cycle = timing_.frame_start_cycle(spec_.first_frame) + *clock;
        w.cycles = *cycles;
      }
    }
    if (!ok)
      throw InputError("--stall", spec,
                       "expected STAGE:CLOCK:CYCLES with STAGE one of lens, rotate, address, fetch, compose, filter, "
                       "CLOCK a whole number and CYCLES 1 .. 1000000000");
    if (fidelity_ != scm::Fidelity::Detailed && fidelity_ != scm::Fidelity::Cycle)
      throw InputError("--stall", spec, "stalls exist only at the cycle-accurate levels (cycle, detailed)");
    out.push_back(w);
  }
  return out;
}

void Session::on_scanned_out(const HmdFrame& f, const stage::FrameReport& r) {
  const OutputSpec& o = spec_.out;
  memory_peak_bytes_ = std::max(memory_peak_bytes_, memories_.bytes_allocated());
  const FrameHashes hashes = frame_hashes(f, spec_.threads);
  const std::string& ph = hashes.pixels;
  const std::string& th = hashes.photons;
  const int64_t k = r.frame - spec_.first_frame;
  if (o.every > 0 && k % o.every == 0) {
    host::write_rgb8((fs::path(o.out_dir) / kFrameImage.name(r.frame)).string(), frame_to_image(f));
    ++images_;
    if (o.photon_times) {
      std::string text = "eye,x,y,photon_ps\n";
      for (int e = 0; e < f.eyes; ++e)
        for (int y = 0; y < f.height; ++y)
          for (int x = 0; x < f.width; ++x)
            text += std::to_string(e) + "," + std::to_string(x) + "," + std::to_string(y) + "," +
                    std::to_string(f.photon_ps[f.index(e, x, y)]) + "\n";
      write_text_atomic((fs::path(o.out_dir) / kPhotonTimes.name(r.frame)).string(), text);
    }
  }
  const auto [lo, hi] = dp::LatchRule(spec_.config).frame_samples(stream_, r.frame);
  nlohmann::json row = frame_row(r, lo, hi, ph, th);
  if (!timed_frames_.every_frame()) row["level"] = timed_frames_.contains(r.frame) ? "detailed" : "functional";
  if (probe_ && k % o.error_every == 0) {
    nlohmann::json err;
    const auto w0 = Clock::now();
    probe_->measure(f, r.frame, err);
    probe_wall_s_ += std::chrono::duration<double>(Clock::now() - w0).count();
    row["error"] = err["error"];
  }
  log_->add(row, frame_csv_row(r, ph, th));
  if (on_frame) on_frame(f, r);
}

RunSummary Session::run() {
  const OutputSpec& o = spec_.out;
  scm::TimedRunOptions opt;
  opt.fidelity = fidelity_;
  opt.threads = spec_.threads;
  opt.speculate = spec_.speculate;
  opt.clock_gating = spec_.clock_gating;
  opt.progress = on_progress;
  if (live_ && on_progress)  // a live run slower than the display says how far behind the tracker it is
    opt.progress = [this](double f, const std::string& what) { on_progress(f, what + live_lag_text()); };
  int stop_signal = 0;
  if (stop_when) opt.stop = [this, &stop_signal] { return (stop_signal = stop_when()) != 0; };
  build_outputs(opt);

  stage::TimedInputs in;
  in.config = spec_.config;
  in.memories = &memories_;
  in.orientation = &stream_;
  in.first_frame = spec_.first_frame;
  in.frames = spec_.frames;
  in.timed_frames = timed_frames_;
  in.stalls = stalls_;
  if (live_) build_live_input(in);
  if (host_)
    in.before_frame = [this](int64_t frame, double tt) {
      const auto w0 = Clock::now();
      host_->before_frame(frame, tt);
      host_wall_s_ += std::chrono::duration<double>(Clock::now() - w0).count();
      baseline_triangles_ += host_->full_render_triangles(tt);
    };
  // Error against the truth (TruthProbe): every --error-every-th frame of a walk.
  if (host_ && o.error_every > 0) {
    TruthProbeSetup ps;
    ps.config = &spec_.config;
    ps.scene = scene_.get();
    ps.walk = walk_.get();
    ps.host = host_.get();
    ps.memories = &memories_;
    ps.orientation = &stream_;
    ps.segmented = regions_ ? &segmented_ : nullptr;
    ps.ipd_m = spec_.memories.checked_ipd_m();
    ps.threads = spec_.threads;
    ps.first_frame = spec_.first_frame;
    ps.frames = spec_.frames;
    ps.every = o.error_every;
    ps.truth_face_size = o.truth_face_size;
    ps.supersample = o.truth_supersample;
    ps.tear_image = o.tear_image;
    ps.tear_at = o.tear_at;
    probe_ = std::make_unique<TruthProbe>(ps);
  }
  std::vector<int64_t> medians;
  int64_t worst = 0, best = INT64_MAX;
  in.sink = [&](const HmdFrame& f, const stage::FrameReport& r) {
    worst = std::max(worst, r.latency_max_ps);
    best = std::min(best, r.latency_min_ps);
    medians.push_back(r.latency_median_ps);
    on_scanned_out(f, r);
    advance_motion(r.frame);
  };

  scm::TimedResult res;
  try {
    res = scm::run_timed(in, opt);
  } catch (...) {
    if (!vcd_tmp_base_.empty()) discard_temp_file(vcd_tmp_base_ + ".vcd");
    throw;
  }
  RunSummary s;
  if (!vcd_final_.empty()) {
    commit_temp_file(vcd_tmp_base_ + ".vcd", vcd_final_);
    s.vcd = vcd_final_;
    s.gtkw = fs::path(vcd_final_).replace_extension(".gtkw").string();
    // The view opens on the traced window's first two lines.
    const int64_t two_lines = timing_.cycles_to_ps(2 * int64_t{spec_.config.timing.h_total()});
    write_text_atomic(s.gtkw, gtkw_for_vcd(vcd_final_, fs::path(vcd_final_).filename().string(), two_lines));
  }
  std::sort(medians.begin(), medians.end());
  s.fidelity = timed_frames_.every_frame() ? scm::to_string(fidelity_) : "functional";  // the detailed windows: s.detail
  s.motion_source = motion_source_;
  s.memory_source = memory_source_;
  s.first_frame = spec_.first_frame;
  s.frames = spec_.frames;
  s.frames_done = res.frames;
  s.stop_signal = res.stopped ? stop_signal : 0;
  s.latency_min_ps = res.frames ? best : 0;
  s.latency_median_ps = res.frames ? medians[medians.size() / 2] : 0;
  s.latency_max_ps = worst;
  s.cycle_accurate = fidelity_ == scm::Fidelity::Detailed || fidelity_ == scm::Fidelity::Cycle;
  if (!timed_frames_.every_frame()) s.detail = detail_text(timed_frames_, spec_, res);
  s.underflows = res.underflows;
  s.late_discarded = res.late_discarded;
  s.swaps = res.swaps;
  s.systemc_modules = res.modules;
  s.memory_bytes_peak = static_cast<int64_t>(std::max(memory_peak_bytes_, memories_.bytes_allocated()));
  s.memory_bytes_hardware = display_memory_bytes(spec_.config);
  s.memory_bytes_hardware_tiled = display_memory_bytes_tiled(spec_.config, memories_);
  s.memory_bytes_hardware_pooled = display_memory_bytes_pooled(spec_.config, memories_);
  s.memory_banks = memories_.eyes() * memories_.count();
  s.texels_written = memories_.texels_written();
  s.pixel_clocks = res.end_cycle - res.first_cycle;
  s.wall_seconds = res.wall_seconds;
  s.images = images_;
  s.out_dir = o.out_dir;
  if (motion_started_ && motion_done_ && last_pose_ps_ < end_ps_) {
    char b[160];
    std::snprintf(b, sizeof b, "  note: the trace ends at %.6f s; later pixels hold its last sample (sample-and-hold)",
                  ps_to_seconds(last_pose_ps_));
    s.notes.push_back(b);
  }
  // A sparse trace's own sample period is part of every latency measured: say so when it is a large part.
  if (trace_summary_ && trace_summary_->median_period_s > 0 && res.frames) {
    const double hold_ps = trace_summary_->median_period_s * 0.5e12, median = static_cast<double>(s.latency_median_ps);
    if (hold_ps >= 0.25 * median) {
      char b[400];
      std::snprintf(b, sizeof b,
                    "  note: the trace's samples are %.3f ms apart (%.1f Hz): a pixel's sample is on average %.3f ms old "
                    "before the pipeline adds its own, %s of the median latency %.3f ms (resample the trace, "
                    "`arpsim tracker import --resample`, or record faster to measure the pipeline alone)",
                    trace_summary_->median_period_s * 1e3, trace_summary_->rate_hz(), hold_ps * 1e-9,
                    hold_ps >= 0.5 * median ? "most" : "a large part", median * 1e-9);
      s.notes.push_back(b);
    }
  }
  if (live_) {
    tracker::StreamStats st;
    live_->usb_stats(st);
    char b[300];
    if (st.dropped_unconsumed > 0) {
      std::snprintf(b, sizeof b,
                    "  note: the run fell up to %.1f s behind the tracker, past the %g s of samples the stream keeps: the "
                    "oldest %" PRId64 " samples were dropped (live.device_dropped_unconsumed)",
                    static_cast<double>(live_behind_max_ps_) * 1e-12, tracker::RiftStreamOptions{}.max_pending_s, st.dropped_unconsumed);
      s.notes.push_back(b);
    } else if (live_behind_max_ps_ * timing_.refresh_hz() >= 1e12) {
      std::snprintf(b, sizeof b, "  note: the run fell up to %.1f s behind the tracker; every sample was still taken (the stream keeps %g s)",
                    static_cast<double>(live_behind_max_ps_) * 1e-12, tracker::RiftStreamOptions{}.max_pending_s);
      s.notes.push_back(b);
    }
  }
  if (const int64_t lost = memories_.writes_lost(); lost > 0) {
    char b[400];
    std::snprintf(b, sizeof b,
                  "  warning: %" PRId64 " texels the host drew fell on cube faces memory.faces leaves out (%s) and were lost: the "
                  "configuration was planned for another scene or motion, or for eyes closer together (arpsim plan; footprint.texels_lost_on_absent_faces)",
                  lost, spec_.config.memory.absent_face_names().c_str());
    s.notes.push_back(b);
  }
  if (const int64_t lost = memories_.writes_lost_off_tiles(); lost > 0) {
    char b[500];
    std::snprintf(b, sizeof b,
                  "  warning: %" PRId64 " texels the host drew fell on tiles memory.tiles leaves out and were lost: the "
                  "tiles were listed for another scene or motion, or a run with wider eyes, --baseline, --regions or another "
                  "theta_t than the plan's (arpsim plan; footprint.texels_lost_off_tiles)",
                  lost);
    s.notes.push_back(b);
  }
  if (const int64_t lost = memories_.writes_lost_pool_full(); lost > 0) {
    std::string full;  // the memories whose pool ran out, and their slots
    for (int k = 0; k < memories_.count(); ++k) {
      int64_t n = 0;
      for (int e = 0; e < memories_.eyes(); ++e) n += memories_.bank(e, k).writes_lost_pool_full();
      if (n > 0) full += (full.empty() ? "memory " : ", ") + std::to_string(k) + " (" + std::to_string(spec_.config.memory.pool_slots(k)) + " slots)";
    }
    char b[600];
    std::snprintf(b, sizeof b,
                  "  warning: %" PRId64 " texels drawn into the display memories were lost for want of a tile slot: the tile pool of %s "
                  "was full when they were drawn (memory.tile_pool was sized for another scene, motion or theta_t, or "
                  "is too small; footprint.texels_lost_tile_pool_full)",
                  lost, full.c_str());
    s.notes.push_back(b);
  }
  if (host_ && !regions_ && !spec_.host.baseline && host_->scheduler().held_slower() > 0) {
    char b[500];
    std::snprintf(b, sizeof b,
                  "  warning: memory.assignment kept objects in memories slower than the priority rule put them %" PRId64
                  " times (object-frames): their images may have moved more than theta_t (%g deg) before they were "
                  "re-rendered (host.object_frames_held_slower_by_assignment)",
                  host_->scheduler().held_slower(), rad_to_deg(host_->scheduler().threshold_rad()));
    s.notes.push_back(b);
  }
  if (!o.tear_image.empty() && probe_) s.notes.push_back(probe_->write_tear_image());

  nlohmann::json r = pipeline_report(res, spec_.config, vcd_final_);
  r["complete"] = s.complete();
  if (!timed_frames_.every_frame()) {
    nlohmann::json windows = nlohmann::json::array();
    for (const auto& [f0, f1] : timed_frames_.windows()) windows.push_back({f0, f1});
    // The run is the functional level with detailed windows, as the summary says; the pipeline, FIFO and
    // stage figures are the detailed level's, over its frames.
    r["fidelity"] = s.fidelity;
    r["fidelity_description"] = std::string(scm::describe(scm::Fidelity::Functional)) + "; the detailed level in the windows of `detail`";
    r["detail"] = {{"level", scm::to_string(fidelity_)},
                   {"windows", windows},
                   {"warmup_frames", spec_.detail_warmup},
                   {"frames_detailed", res.frames - res.untimed_frames},
                   {"frames_functional", res.untimed_frames}};
    if (auto_detail_)
      r["detail"]["auto"] = {{"speed_threshold_dps", spec_.detail_speed_dps},
                             {"frames_over_speed", auto_fast_frames_},
                             {"frames_with_a_stall", auto_stall_frames_}};
  }
  r["frames_done"] = s.frames_done;
  r["motion"] = motion_source_;
  r["cube_map"] = memory_source_;
  r["images"] = images_;
  // What was modelled: the display memories' storage (sparse tiles, both buffers) against what the
  // configuration's hardware holds (the faces present of every memory, double-buffered), what the host
  // drew on faces and tiles the configuration leaves out and stored on the others, the banks (eyes x memories) and the
  // SystemC modules elaborated.
  nlohmann::json tiles_drawn_on = nlohmann::json::array();  // per memory, every eye's bank
  nlohmann::json most_at_once = nlohmann::json::array();  // per memory, the most of its banks
  for (int k = 0; k < memories_.count(); ++k) {
    tiles_drawn_on.push_back(memories_.tiles_ever_written(k));
    most_at_once.push_back(memories_.tiles_most_at_once(k));
  }
  r["footprint"] = {{"display_memory_bytes_peak", s.memory_bytes_peak},
                    {"display_memory_tiles_at_end", memories_.tiles_allocated()},
                    {"display_memory_faces", spec_.config.memory.faces_present()},
                    {"texels_lost_on_absent_faces", memories_.writes_lost()},
                    {"texels_lost_off_tiles", memories_.writes_lost_off_tiles()},
                    {"texels_lost_tile_pool_full", memories_.writes_lost_pool_full()},
                    {"texels_written", s.texels_written},
                    {"display_memory_banks", s.memory_banks},
                    {"systemc_modules", s.systemc_modules},
                    {"display_memory_bytes_hardware", s.memory_bytes_hardware},
                    {"display_memory_tiles_drawn_on", tiles_drawn_on},
                    {"display_memory_bytes_hardware_tiled", s.memory_bytes_hardware_tiled},
                    {"display_memory_tiles_most_at_once", most_at_once},
                    {"display_memory_bytes_hardware_pooled", s.memory_bytes_hardware_pooled}};
  if (trace_summary_) {
    const tracker::MotionSummary& m = *trace_summary_;
    r["trace"] = {{"samples", m.samples},           {"rate_hz", m.rate_hz()},       {"gaps", m.gaps},
                  {"longest_gap_s", m.longest_gap_s}, {"bursts", m.bursts},           {"same_time", m.same_time},
                  {"repeats", m.repeats},            {"peak_speed_dps", m.peak_speed_dps}, {"p99_speed_dps", m.p99_speed_dps},
                  {"max_tilt_deg", m.max_tilt_deg},  {"warnings", tracker::motion_warnings(m)}};
  }
  if (live_) {
    tracker::StreamStats st;
    live_->usb_stats(st);
    // What arrived after the last frame was taken is counted too, so every sample the device sent up to
    // the stats is accounted for: samples + samples_before_start + samples_out_of_order + samples_after_end +
    // device_dropped_unconsumed >= device_samples.
    std::vector<tracker::PoseSample> rest;
    live_->poll(rest, 0);
    r["live"] = {{"source", motion_source_},
                 {"samples", live_intake_->taken()},
                 {"samples_before_start", live_intake_->before_start()},
                 {"samples_out_of_order", live_intake_->out_of_order()},
                 {"samples_after_end", rest.size()},
                 {"samples_held_max", live_held_max_}};
    tracker::for_each_counter(st, [&r](const char* name, int64_t v) { r["live"]["device_" + std::string(name)] = v; });
    r["live"]["device_gap_s"] = st.gap_s;
    r["live"]["behind_max_s"] = static_cast<double>(live_behind_max_ps_) * 1e-12;
    r["live"]["behind_at_end_s"] = static_cast<double>(live_behind_ps_) * 1e-12;
    r["live"]["connected_at_end"] = live_->connected();
    if (live_intake_->recording()) {
      r["live"]["recorded"] = {{"file", spec_.record_live}, {"samples", live_intake_->recorded()}};
      live_intake_->commit_record();
    }
  }
  if (host_) {
    const double px_rad = deg_to_rad(spec_.config.lens.fov_deg) / spec_.config.timing.h_active;
    r["host"] = host_report(*host_, spec_, timing_.refresh_hz(), baseline_triangles_, host_wall_s_, regions_.get(),
                            grid_.get(), segmented_, scene_->objects.size(), px_rad);
    if (probe_ && probe_->measured()) {
      r["host"]["error"] = probe_->summary();
      r["host"]["error"]["wall_seconds"] = probe_wall_s_;  // the truth's own work: not the pipeline's, not the host's
    }
    if (!o.host_csv.empty()) write_text_atomic(o.host_csv, host_csv(r["host"]["memories"]));
  }
  log_->finish(o.report.empty() ? nlohmann::json() : r);
  return s;
}

}  // namespace arp::sim
