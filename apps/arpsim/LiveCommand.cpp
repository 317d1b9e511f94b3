// arpsim live: a window (SDL2) showing the stereo HMD output at the display
// rate as the head moves -- synthetic motion, a trace, or a real tracker on
// USB -- computed by the functional model frame by frame, with the frame's
// orientation-sample-to-photon latency overlaid. `--screenshot` saves what
// the window showed last (read back from the renderer), which is how the
// headless test under Xvfb checks it.
#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "Commands.hpp"
#include "CommonOptions.hpp"
#include "FrameImage.hpp"
#include "MotionOptions.hpp"
#include "PoseConversion.hpp"
#include "common/InputError.hpp"
#include "host/cubemap/BitmapFont.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "tracker/PoseSource.hpp"

namespace arp::app {

namespace {

struct LiveArgs {
  ConfigOptions cfg;
  CubeMapOptions cubemap;
  MotionOptions motion;
  std::string trace, live, screenshot;
  double seconds = 0;
  int scale = 1, threads = 0;
  bool quiet = false;
};

// SDL resources, released in reverse order whatever happens.
struct Sdl {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  ~Sdl() {
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
  }
};

// The overlay: a dark box with white text in the image's top-left corner.
void overlay(host::RgbImage& img, const std::vector<std::string>& lines) {
  constexpr int kScale = 2, kLine = 9 * kScale, kPad = 6;
  int w = 0;
  for (const auto& l : lines) w = std::max(w, host::text_width(l, kScale));
  const int bw = std::min(img.width, w + 2 * kPad), bh = std::min(img.height, static_cast<int>(lines.size()) * kLine + 2 * kPad);
  for (int y = 0; y < bh; ++y)
    for (int x = 0; x < bw; ++x) {
      uint8_t* p = img.px(x, y);
      p[0] = p[1] = p[2] = 16;
    }
  for (size_t i = 0; i < lines.size(); ++i)
    host::draw_text(lines[i], kPad, kPad + static_cast<int>(i) * kLine, kScale, [&](int x, int y) {
      if (x >= 0 && y >= 0 && x < bw && y < bh) {
        uint8_t* p = img.px(x, y);
        p[0] = p[1] = p[2] = 255;
      }
    });
}

int run_live(const LiveArgs& a) {
  dp::ArpConfig c = a.cfg.resolve();
  const auto issues = dp::validate(c);
  if (!issues.empty()) throw InputError(a.cfg.file.empty() ? "configuration" : a.cfg.file, issues.front().key, issues.front().reason);
  if (!(a.seconds >= 0) || a.seconds > 24 * 3600) throw InputError("--seconds", "", "must be 0 (until the window closes) .. a day");
  if (a.scale < 1 || a.scale > 8) throw InputError("--scale", "", "must be 1 .. 8");
  const int sources = (!a.trace.empty()) + a.motion.given() + (!a.live.empty());
  if (sources > 1) throw InputError("--trace", "", "give one of --trace, --motion and --live");
  if (!a.live.empty() && a.live != "usb") throw InputError("--live", a.live, "the live source is usb (an Oculus Rift DK1/DK2)");
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") && !std::getenv("SDL_VIDEODRIVER")) {
    std::fprintf(stderr, "arpsim live: no display to open a window on; run it on a desktop, or headless: xvfb-run -a arpsim live ...\n");
    return 1;
  }
  const FunctionalModel model(c);
  const dp::VideoTiming& t = model.timing();
  const double period_s = 1.0 / t.refresh_hz();
  const int64_t frames = a.seconds > 0 ? std::max<int64_t>(1, static_cast<int64_t>(std::llround(a.seconds / period_s))) : INT64_MAX;

  // The head motion, from one pose source: all of it up front (trace,
  // synthetic) or as it arrives (usb).
  std::unique_ptr<tracker::PoseSource> source;
  if (!a.trace.empty()) {
    source = tracker::trace_file_source(a.trace);
  } else if (!a.live.empty()) {
    std::string err;
    if (!(source = tracker::usb_source(err))) {
      std::fprintf(stderr, "arpsim live: --live usb: %s\n", err.c_str());
      return 1;
    }
  } else {
    MotionOptions m = a.motion;
    if (!m.given()) {
      m.motion = "shake";
      m.peak = 100;
    }
    const double span = a.seconds > 0 ? a.seconds + 1.0 : 3600.0;
    source = tracker::recorded_source(m.make(0.0, span), "synthetic " + m.motion);  // the motion starts with frame 0
  }
  const std::string source_name = source->describe();
  dp::OrientationStream stream = dp::OrientationStream::constant(dp::Quat{});
  std::vector<tracker::PoseSample> got;
  if (!source->live()) {
    source->poll(got, 0);
    stream = dp::OrientationStream(to_orientation_samples(got), source_name);
    got.clear();
  }
  tracker::PoseSource* usb = source->live() ? source.get() : nullptr;
  std::string memory_source;
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  a.cubemap.fill(mem, dp::Quat{}, memory_source);

  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr, "arpsim live: cannot start SDL video: %s\n", SDL_GetError());
    return 1;
  }
  Sdl sdl;
  const int iw = c.timing.h_active * c.timing.eyes, ih = c.timing.v_active;
  sdl.window = SDL_CreateWindow("arpsim live", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, iw * a.scale, ih * a.scale, 0);
  if (!sdl.window) {
    std::fprintf(stderr, "arpsim live: cannot open a window: %s\n", SDL_GetError());
    return 1;
  }
  sdl.renderer = SDL_CreateRenderer(sdl.window, -1, SDL_RENDERER_SOFTWARE);  // readable back for screenshots, everywhere
  if (!sdl.renderer || !(sdl.texture = SDL_CreateTexture(sdl.renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, iw, ih))) {
    std::fprintf(stderr, "arpsim live: cannot draw into the window: %s\n", SDL_GetError());
    return 1;
  }

  RenderOptions ro;
  ro.threads = a.threads;
  ro.photon_times = true;
  HmdFrame f;
  host::RgbImage shown;
  const auto wall0 = std::chrono::steady_clock::now();
  const int64_t usb_offset = usb ? -usb->now_ps() : 0;
  int64_t shown_frames = 0, late = 0;
  double render_ms_sum = 0;
  bool quit = false;
  for (int64_t k = 0; k < frames && !quit; ++k) {
    // Frame k goes up at k periods after the start; wait for it, taking tracker data meanwhile.
    const auto due = wall0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(static_cast<double>(k + 1) * period_s));
    while (std::chrono::steady_clock::now() < due) {
      if (usb) usb->poll(got, 1);
      else SDL_Delay(1);
    }
    if (std::chrono::steady_clock::now() > due + std::chrono::duration<double>(period_s)) ++late;
    SDL_Event e;
    while (SDL_PollEvent(&e))
      if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) quit = true;
    if (usb) {
      append_live_poses(stream, got, usb_offset, source_name);
      got.clear();
      for (const auto& ev : usb->take_events()) std::fprintf(stderr, "arpsim live: %s\n", ev.c_str());
    }
    const auto r0 = std::chrono::steady_clock::now();
    model.render(mem, stream, k, f, ro);
    const double render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r0).count();
    render_ms_sum += render_ms;
    // Orientation sample -> photon over a grid of pixels (every 8th pixel and line).
    std::vector<int64_t> lat;
    for (int y = 0; y < f.height; y += 8)
      for (int x = 0; x < f.width; x += 8) {
        const size_t s = model.latch_rule().sample(stream, k, 0, x, y);
        lat.push_back(f.photon_ps[f.index(0, x, y)] - stream[s].time_ps);
      }
    std::sort(lat.begin(), lat.end());
    shown = frame_to_image(f);
    char l1[160], l2[160], l3[160];
    std::snprintf(l1, sizeof l1, "ARPSIM LIVE  FRAME %" PRId64 "  %.2f HZ  LATCH %s", k, t.refresh_hz(), dp::to_string(c.pipeline.latch).c_str());
    std::snprintf(l2, sizeof l2, "SAMPLE TO PHOTON US: MIN %.1f  MEDIAN %.1f  MAX %.1f", static_cast<double>(lat.front()) * 1e-6,
                  static_cast<double>(lat[lat.size() / 2]) * 1e-6, static_cast<double>(lat.back()) * 1e-6);
    std::snprintf(l3, sizeof l3, "RENDER %.1f MS  %s%s", render_ms, source_name.c_str(),
                  usb && !usb->connected() ? "  DISCONNECTED - HOLDING" : "");
    std::vector<std::string> text{l1, l2, l3};
    for (auto& line : text)
      for (char& ch : line) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));  // the font's capitals
    overlay(shown, text);
    SDL_UpdateTexture(sdl.texture, nullptr, shown.rgb.data(), iw * 3);
    SDL_RenderClear(sdl.renderer);
    SDL_RenderCopy(sdl.renderer, sdl.texture, nullptr, nullptr);
    if (!a.screenshot.empty() && (k + 1 == frames || quit)) {
      // What the window shows, read back from the renderer.
      host::RgbImage shot(iw * a.scale, ih * a.scale);
      if (SDL_RenderReadPixels(sdl.renderer, nullptr, SDL_PIXELFORMAT_RGB24, shot.rgb.data(), shot.width * 3) != 0) {
        std::fprintf(stderr, "arpsim live: cannot read the window back: %s\n", SDL_GetError());
        return 1;
      }
      host::write_rgb8(a.screenshot, shot);
    }
    SDL_RenderPresent(sdl.renderer);
    ++shown_frames;
    if (!a.quiet && k % 30 == 0) std::fprintf(stderr, "\r  frame %" PRId64 "  %s", k, l2);
  }
  if (!a.quiet) std::fprintf(stderr, "\n");
  std::printf("arpsim live: %" PRId64 " frames of %s at %.2f Hz (%" PRId64 " late), mean render %.2f ms%s%s\n", shown_frames,
              source_name.c_str(), t.refresh_hz(), late, render_ms_sum / static_cast<double>(std::max<int64_t>(1, shown_frames)),
              a.screenshot.empty() ? "" : "; screenshot ", a.screenshot.c_str());
  return 0;
}

}  // namespace

Runner add_live_command(CLI::App& app) {
  auto a = std::make_shared<LiveArgs>();
  CLI::App* cmd = app.add_subcommand("live", "A window showing the HMD output at the display rate as the head moves (SDL2)");
  a->cfg.add_to(*cmd);
  a->cubemap.add_to(*cmd);
  a->motion.add_to(*cmd, false);
  cmd->add_option("--trace", a->trace, "Head motion from a trace file (CSV, docs/tracker.md)");
  cmd->add_option("--live", a->live, "Head motion from a tracker: usb (the first Oculus Rift DK1/DK2)");
  cmd->add_option("--seconds", a->seconds, "Run this long (0: until the window is closed or Esc)")->capture_default_str();
  cmd->add_option("--scale", a->scale, "Window pixels per display pixel")->capture_default_str();
  cmd->add_option("--screenshot", a->screenshot, "Save what the window showed last (PNG, ... by extension)");
  cmd->add_option("--threads", a->threads, "Worker threads of the functional model (0: all cores)")->check(CLI::Range(0, 256));
  cmd->add_flag("--quiet,-q", a->quiet, "No progress line");
  return [a] { return run_live(*a); };
}

}  // namespace arp::app
