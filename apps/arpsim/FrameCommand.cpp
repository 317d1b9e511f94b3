// arpsim frame: one stereo HMD frame of a cube map (or the calibration
// pattern) at one head orientation, written as an image.
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <cmath>
#include <cstdlib>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "FrameImage.hpp"
#include "sim/ConfigFile.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "common/InputError.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

namespace arp::app {

namespace {
struct FrameArgs {
  ConfigOptions cfg;
  double yaw = 0, pitch = 0, roll = 0;
  std::string quat;
  CubeMapOptions cubemap;
  std::string out = "frame.png";
  std::string report;
  std::string aa;
  int64_t frame = 0;
  int threads = 0;
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

int run_frame(const FrameArgs& a) {
  dp::ArpConfig c = a.cfg.resolve();
  if (!a.aa.empty() && !dp::parse(a.aa, c.pipeline.aa)) throw InputError("--aa", "", "must be off or bilinear");
  for (double v : {a.yaw, a.pitch, a.roll})
    if (!std::isfinite(v)) throw InputError("--yaw/--pitch/--roll", "", "angles must be finite");
  const dp::Quat q = a.quat.empty() ? dp::normalised(dp::from_yaw_pitch_roll_deg(a.yaw, a.pitch, a.roll), "orientation")
                                    : parse_quat(a.quat);
  const FunctionalModel model(c);
  const int S = c.memory.face_size;
  std::string source;
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  a.cubemap.fill(mem, q, source);
  (void)S;

  HmdFrame f;
  RenderOptions ro;
  ro.threads = a.threads;
  ro.photon_times = true;
  const auto t0 = std::chrono::steady_clock::now();
  model.render(mem, dp::OrientationStream::constant(q), a.frame, f, ro);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  host::write_rgb8(a.out, frame_to_image(f));

  const auto [pmin, pmax] = std::minmax_element(f.photon_ps.begin(), f.photon_ps.end());
  std::printf("arpsim frame: %s -> %s (%dx%d, %s, %d eye%s)\n", source.c_str(), a.out.c_str(), f.width * f.eyes,
              f.height, dp::to_string(c.pipeline.aa).c_str(), f.eyes, f.eyes == 2 ? "s side by side" : "");
  std::printf("  orientation q = (%.6f, %.6f, %.6f, %.6f)  frame %lld at %.3f Hz\n", q.w, q.x, q.y, q.z,
              static_cast<long long>(a.frame), model.timing().refresh_hz());
  std::printf("  photon times %.6f .. %.6f ms; display memory in use %.1f MiB; rendered in %.1f ms (wall clock)\n",
              static_cast<double>(*pmin) * 1e-9, static_cast<double>(*pmax) * 1e-9,
              static_cast<double>(mem.bytes_allocated()) / (1 << 20), ms);
  if (!a.report.empty()) {
    nlohmann::json r{{"image", a.out},
                     {"source", source},
                     {"quaternion_wxyz", {q.w, q.x, q.y, q.z}},
                     {"frame", a.frame},
                     {"refresh_hz", model.timing().refresh_hz()},
                     {"first_photon_ps", *pmin},
                     {"last_photon_ps", *pmax},
                     {"display_memory_bytes", mem.bytes_allocated()},
                     {"config", config::to_json(c)}};
    write_text_atomic(a.report, r.dump(2) + "\n");
  }
  return 0;
}
}  // namespace

Runner add_frame_command(CLI::App& app) {
  auto args = std::make_shared<FrameArgs>();
  CLI::App* cmd = app.add_subcommand("frame", "Render one stereo HMD frame of a cube map at one head orientation");
  args->cfg.add_to(*cmd);
  cmd->add_option("--yaw", args->yaw, "Yaw in degrees about +y, positive turns left");
  cmd->add_option("--pitch", args->pitch, "Pitch in degrees about +x, positive looks up");
  cmd->add_option("--roll", args->roll, "Roll in degrees about +z, positive tilts the head left");
  cmd->add_option("--quat", args->quat, "Orientation quaternion w,x,y,z (head frame to world) instead of angles")
      ->type_name("W,X,Y,Z");
  args->cubemap.add_to(*cmd);
  cmd->add_option("--out,-o", args->out, "Output image (PNG, EXR, TIFF... by extension)")->capture_default_str();
  cmd->add_option("--aa", args->aa, "Anti-aliasing: off or bilinear (overrides pipeline.aa)");
  cmd->add_option("--frame", args->frame, "Frame index (sets the photon times)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 256));
  cmd->add_option("--report", args->report, "Also write a JSON report of the frame");
  return [args] { return run_frame(*args); };
}

}  // namespace arp::app
