// arpsim live: a window (SDL2) showing the stereo HMD output at the display
// rate as the head moves -- synthetic motion, a trace, or a real tracker on
// USB -- with the frame's orientation-sample-to-photon latency overlaid. The
// loop is sim::LiveLoop; this command is its window. `--screenshot` saves
// what the window showed last (read back from the renderer), which is how
// the headless test under Xvfb checks it.
#include <SDL.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>

#include "Commands.hpp"
#include "CommonOptions.hpp"
#include "MotionOptions.hpp"
#include "common/InputError.hpp"
#include "common/Interrupt.hpp"
#include "common/OutputPaths.hpp"
#include "host/cubemap/BitmapFont.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "sim/FrameImage.hpp"
#include "sim/LiveLoop.hpp"

namespace arp::app {

namespace {

struct LiveArgs {
  ConfigOptions cfg;
  sim::LiveSpec spec;
  std::string screenshot;
  int scale = 1;
  bool quiet = false;
};

// SDL resources, released in reverse order whatever happens.
struct Sdl {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  void draw() const { SDL_RenderClear(renderer); SDL_RenderCopy(renderer, texture, nullptr, nullptr); }
  ~Sdl() {
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
  }
};

int fail(const char* what) {
  std::fprintf(stderr, "arpsim live: %s: %s\n", what, SDL_GetError());
  return 1;
}

int run_live(LiveArgs& a) {
  a.spec.config = a.cfg.resolve();
  a.spec.config_source = a.cfg.source();
  if (a.scale < 1 || a.scale > 8) throw InputError("--scale", "", "must be 1 .. 8");
  std::vector<NamedPath> inputs = a.spec.memories.input_files();
  inputs.push_back({"--config", a.cfg.file});
  inputs.push_back({"--trace", a.spec.trace});
  check_output_paths({{"--screenshot", a.screenshot}, {"--record-live", a.spec.record_live}}, inputs);
  host::check_image_output("--screenshot", a.screenshot);
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") && !std::getenv("SDL_VIDEODRIVER")) {
    std::fprintf(stderr, "arpsim live: no display to open a window on; run it on a desktop, or headless: xvfb-run -a arpsim live ...\n");
    return 1;
  }
  // Ctrl-C / SIGTERM: close the window after the frame in flight and write what was recorded (not SDL's
  // handler, which would only post a quit event, and none before the window).
  const InterruptGuard ctrl_c;
  sim::LiveLoop loop(a.spec);
  if (const int sig = interrupt_signal()) return interrupted_exit_status(sig);  // (stopped while the memories were filled)
  const auto& c = loop.config();
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) return fail("cannot start SDL video");
  Sdl sdl;
  const int iw = c.timing.h_active * c.timing.eyes, ih = c.timing.v_active;
  sdl.window = SDL_CreateWindow("arpsim live", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, iw * a.scale, ih * a.scale, 0);
  if (!sdl.window) return fail("cannot open a window");
  sdl.renderer = SDL_CreateRenderer(sdl.window, -1, SDL_RENDERER_SOFTWARE);  // readable back for screenshots, everywhere
  if (!sdl.renderer || !(sdl.texture = SDL_CreateTexture(sdl.renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, iw, ih)))
    return fail("cannot draw into the window");
  int64_t shown = 0, progress_at = -30;
  double render_ms = 0;
  bool quit = false;
  while (!loop.finished() && !quit && !interrupt_requested()) {
    const sim::LiveFrame f = loop.next();
    SDL_Event e;
    while (SDL_PollEvent(&e))
      if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) quit = true;
    for (const auto& ev : loop.take_events()) std::fprintf(stderr, "arpsim live: %s\n", ev.c_str());
    render_ms += f.render_ms;
    host::RgbImage img = sim::frame_to_image(*f.frame);
    char l1[160], l2[160], l3[160];
    std::snprintf(l1, sizeof l1, "ARPSIM LIVE  FRAME %" PRId64 "  %.2f HZ  LATCH %s", f.index, loop.refresh_hz(),
                  dp::to_string(c.pipeline.latch).c_str());
    std::snprintf(l2, sizeof l2, "SAMPLE TO PHOTON US: MIN %.1f  MEDIAN %.1f  MAX %.1f", static_cast<double>(f.latency_min_ps) * 1e-6,
                  static_cast<double>(f.latency_median_ps) * 1e-6, static_cast<double>(f.latency_max_ps) * 1e-6);
    std::snprintf(l3, sizeof l3, "RENDER %.1f MS  %s%s", f.render_ms, loop.source_name().c_str(),
                  f.disconnected ? "  DISCONNECTED - HOLDING" : "");
    host::draw_text_box(img, {l1, l2, l3});
    SDL_UpdateTexture(sdl.texture, nullptr, img.rgb.data(), iw * 3);
    sdl.draw();
    SDL_RenderPresent(sdl.renderer);
    ++shown;
    if (!a.quiet && f.index >= progress_at + 30) {  // (about twice a second, however many frames are dropped)
      std::fprintf(stderr, "\r  frame %" PRId64 "  %s", f.index, l2);
      progress_at = f.index;
    }
  }
  if (!a.quiet) std::fprintf(stderr, "\n");
  if (!a.screenshot.empty() && shown > 0) {  // however the loop ended: the last frame shown, still in the texture
    host::RgbImage shot(iw * a.scale, ih * a.scale);
    sdl.draw();  // as the window shows it, read back
    if (SDL_RenderReadPixels(sdl.renderer, nullptr, SDL_PIXELFORMAT_RGB24, shot.rgb.data(), shot.width * 3) != 0)
      return fail("cannot read the window back");
    host::write_rgb8(a.screenshot, shot);
  }
  loop.commit_record();
  std::printf("arpsim live: %" PRId64 " frames of %s at %.2f Hz (%" PRId64 " shown, %" PRId64 " dropped to keep up), mean render %.2f ms%s%s\n",
              shown + loop.dropped_frames(), loop.source_name().c_str(), loop.refresh_hz(), shown, loop.dropped_frames(),
              render_ms / static_cast<double>(std::max<int64_t>(1, shown)),
              a.screenshot.empty() ? "" : shown > 0 ? "; screenshot " : "; no frame shown, no screenshot ", a.screenshot.c_str());
  if (!a.spec.live.empty())
    std::printf("arpsim live: %" PRId64 " tracker samples taken (%" PRId64 " received before the start, %" PRId64 " out of order)%s%s\n",
                loop.live_samples(), loop.live_samples_before_start(), loop.live_samples_out_of_order(), a.spec.record_live.empty() ? "" : "; recorded in ", a.spec.record_live.c_str());
  if (const int sig = interrupt_signal()) return interrupted_exit_status(sig);
  return 0;
}

}  // namespace

Runner add_live_command(CLI::App& app) {
  auto a = std::make_shared<LiveArgs>();
  CLI::App* cmd = a->cfg.add_command(app, "live", "A window showing the HMD output at the display rate as the head moves (SDL2)");
  add_memory_options(*cmd, a->spec.memories);
  add_motion_options(*cmd, a->spec.motion, false, false);  // (no --motion: a default shake these shape)
  cmd->add_option("--trace", a->spec.trace, "Head motion from a trace file (CSV, docs/tracker.md)");
  cmd->add_option("--live", a->spec.live, "Head motion from a tracker: usb (an Oculus Rift DK1/DK2; --device chooses one)");
  add_device_option(*cmd, a->spec.tracker);
  add_record_live_option(*cmd, a->spec.record_live);
  cmd->add_option("--seconds", a->spec.seconds, "Run this long (0: until the window is closed or Esc)")->capture_default_str();
  cmd->add_option("--scale", a->scale, "Window pixels per display pixel")->capture_default_str();
  cmd->add_option("--screenshot", a->screenshot, "Save what the window showed last (PNG, ... by extension)")->check(output_name());
  add_threads_option(*cmd, a->spec.threads);
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run_live(*a); };
}

}  // namespace arp::app
