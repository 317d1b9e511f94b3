// arpsim frame: one stereo HMD frame of a cube map (or the calibration
// pattern) at one head orientation, written as an image.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "sim/FrameImage.hpp"
#include "sim/StillFrame.hpp"
#include "common/StrictJson.hpp"

namespace arp::app {

namespace {
struct FrameArgs {
  ConfigOptions cfg;
  sim::StillSpec spec;
  double yaw = 0, pitch = 0, roll = 0;
  std::string quat, out = "frame.png", report;
  std::optional<std::string> aa;  // given empty is not "not given": it is refused
};

dp::Quat parse_quat(const std::string& s) {
  // strtod, not a stream: "nan" and "inf" must parse so the quaternion check can name them.
  double v[4];
  const char* p = s.c_str();
  for (int i = 0; i < 4; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    if (end == p) throw InputError("--quat", "component " + std::to_string(i), "expected four comma-separated numbers w,x,y,z");
    p = end;
    if (i < 3) {
      if (*p != ',') throw InputError("--quat", "component " + std::to_string(i), "expected four comma-separated numbers w,x,y,z");
      ++p;
    }
  }
  if (*p != '\0') throw InputError("--quat", "", std::string("unexpected text after four numbers: ") + p);
  return dp::normalised(dp::Quat{v[0], v[1], v[2], v[3]}, "--quat");
}

int run_frame(FrameArgs& a) {
  sim::StillSpec& spec = a.spec;
  // --aa is pipeline.aa, applied with the configuration before it is checked (texel_frac 0 is valid without
  // bilinear filtering: applied after, the check refused it).
  dp::AaMode aa{};
  if (a.aa && !dp::parse(*a.aa, aa)) throw InputError("--aa", *a.aa, "must be off or bilinear");
  if (a.aa) a.cfg.sets.push_back("pipeline.aa=" + *a.aa);
  spec.config = a.cfg.resolve();
  spec.config_source = a.cfg.source();
  for (double v : {a.yaw, a.pitch, a.roll})
    if (!std::isfinite(v)) throw InputError("--yaw/--pitch/--roll", "", "angles must be finite");
  spec.orientation = a.quat.empty() ? dp::normalised(dp::from_yaw_pitch_roll_deg(a.yaw, a.pitch, a.roll), "orientation")
                                    : parse_quat(a.quat);
  std::vector<NamedPath> inputs = spec.memories.input_files();
  inputs.push_back({"--config", a.cfg.file});
  check_output_paths({{"--out", a.out}, {"--report", a.report}}, inputs);
  host::check_image_output("--out", a.out);
  const sim::StillFrame s = sim::render_still(spec);
  const HmdFrame& f = s.frame;
  const dp::Quat& q = spec.orientation;
  host::write_rgb8(a.out, sim::frame_to_image(f));
  std::printf("arpsim frame: %s -> %s (%dx%d, %s, %d eye%s)\n", s.source.c_str(), a.out.c_str(), f.width * f.eyes, f.height,
              dp::to_string(spec.config.pipeline.aa).c_str(), f.eyes, f.eyes == 2 ? "s side by side" : "");
  std::printf("  orientation q = (%.6f, %.6f, %.6f, %.6f)  frame %lld at %.3f Hz\n", q.w, q.x, q.y, q.z,
              static_cast<long long>(spec.frame), s.refresh_hz);
  std::printf("  photon times %.6f .. %.6f ms; display memory in use %.1f MiB; rendered in %.1f ms (wall clock)\n",
              static_cast<double>(s.first_photon_ps) * 1e-9, static_cast<double>(s.last_photon_ps) * 1e-9,
              static_cast<double>(s.memory_bytes) / (1 << 20), s.render_ms);
  if (s.lost_on_absent_faces + s.lost_off_tiles > 0)
    std::printf("  warning: %lld texels fell on faces (memory.faces) or tiles (memory.tiles) the configuration leaves out and were "
                "lost: it was planned for another scene or motion\n",
                static_cast<long long>(s.lost_on_absent_faces + s.lost_off_tiles));
  if (s.lost_pool_full > 0)
    std::printf("  warning: %lld texels were lost for want of a tile slot: a tile pool (memory.tile_pool) was full when they "
                "were drawn (it was sized for another scene or motion, or is too small)\n",
                static_cast<long long>(s.lost_pool_full));
  if (!a.report.empty()) write_text_atomic(a.report, dump_json(sim::still_report(spec, s, a.out), 2) + "\n");
  return 0;
}
}  // namespace

Runner add_frame_command(CLI::App& app) {
  auto args = std::make_shared<FrameArgs>();
  CLI::App* cmd = args->cfg.add_command(app, "frame", "Render one stereo HMD frame of a cube map at one head orientation");
  CLI::Option* yaw = cmd->add_option("--yaw", args->yaw, "Yaw in degrees about +y, positive turns left");
  CLI::Option* pitch = cmd->add_option("--pitch", args->pitch, "Pitch in degrees about +x, positive looks up");
  CLI::Option* roll = cmd->add_option("--roll", args->roll, "Roll in degrees about +z, positive tilts the head left");
  cmd->add_option("--quat", args->quat, "Orientation quaternion w,x,y,z (head frame to world) instead of angles")
      ->type_name("W,X,Y,Z")
      ->excludes(yaw)
      ->excludes(pitch)
      ->excludes(roll);
  add_memory_options(*cmd, args->spec.memories);
  cmd->add_option("--out,-o", args->out, "Output image (PNG, EXR, TIFF... by extension)")->capture_default_str()->check(output_name());
  cmd->add_option("--aa", args->aa, "Anti-aliasing: off or bilinear (overrides pipeline.aa)");
  cmd->add_option("--frame", args->spec.frame, "Frame index (sets the photon times)")
      ->check(CLI::Range(int64_t{0}, std::numeric_limits<int64_t>::max()));
  add_threads_option(*cmd, args->spec.threads);
  cmd->add_option("--report", args->report, "Also write a JSON report of the frame")->check(output_name());
  return [args] { return run_frame(*args); };
}

}  // namespace arp::app
