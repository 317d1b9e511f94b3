// arpsim's two hot paths against what a user would pick instead, Mesa's
// llvmpipe (software OpenGL through EGL surfaceless), side by side in one run
// on one machine, best of N interleaved repetitions (a neighbour on a shared
// machine only ever slows a run down; interleaving gives both sides the same
// neighbours):
//
// - host rendering: the gallery (every object, six 512^2 faces from the walk's
//   first point) by host::CubeFaceRenderer and by host::GlCubeRenderer, both
//   ending in a display memory bank (GL reads colour, depth code and object
//   back), at LP_NUM_THREADS 1 and 2;
// - the per-pixel path: FunctionalModel::render against bench::GlPerPixel on
//   the same display memories, nearest and bilinear, one memory written or
//   all four, 1 and 2 threads on both sides; llvmpipe with the leanest texel
//   (RGBA8, the depth code's high byte) and with arpsim's (RGBA16).
//
// Each row also says how far the two agree (the same visible object per texel;
// the same display colour per pixel), and the per-pixel rows their share of
// the STREAM copy bound measured in the same run; the one-thread rows also
// arpsim's cycles per pixel at the core's clock measured in the same run
// (bench/CoreClock.hpp: this VM has no cycle counter).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <thread>
#include <tuple>
#include <string>
#include <vector>

#include "BenchInputs.hpp"
#include "CoreClock.hpp"
#include "GlPerPixel.hpp"
#include "common/AtomicFile.hpp"
#include "common/ProgressLine.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/render/gl/GlCubeRenderer.hpp"
#include "host/scene/Gallery.hpp"

namespace {

using namespace arp;
using Clock = std::chrono::steady_clock;

// Calls of `work` per second over at least `min_s`.
double rate(const std::function<void()>& work, double min_s) {
  work();  // warm: caches, JIT-compiled shaders, first-touch pages
  const auto t0 = Clock::now();
  int64_t n = 0;
  double s = 0;
  do {
    work();
    ++n;
    s = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (s < min_s);
  return static_cast<double>(n) / s;
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

// Texels where either renderer shows an object: the share where both show the same one.
double same_object(const std::vector<host::FaceImage>& a, const std::vector<host::FaceImage>& b) {
  int64_t either = 0, same = 0;
  for (size_t f = 0; f < 6; ++f) {
    const auto& x = a[f].object;
    const auto& y = b[f].object;
    const size_t n = std::max(x.size(), y.size());
    for (size_t k = 0; k < n; ++k) {
      const uint32_t p = k < x.size() ? x[k] : 0, q = k < y.size() ? y[k] : 0;
      if (p == 0 && q == 0) continue;
      ++either;
      same += p == q ? 1 : 0;
    }
  }
  return either ? static_cast<double>(same) / static_cast<double>(either) : 1.0;
}

// Pixels whose three channels differ by at most `tol` (HmdFrame R:G:B against GL's RGBA bytes).
double same_colour(const HmdFrame& f, const std::vector<uint32_t>& rgba, int tol) {
  int64_t same = 0;
  for (size_t i = 0; i < f.pixels.size(); ++i) {
    const uint32_t p = f.pixels[i], q = rgba[i];
    const int d[3] = {static_cast<int>((p >> 16) & 0xFF) - static_cast<int>(q & 0xFF),
                      static_cast<int>((p >> 8) & 0xFF) - static_cast<int>((q >> 8) & 0xFF),
                      static_cast<int>(p & 0xFF) - static_cast<int>((q >> 16) & 0xFF)};
    same += (std::abs(d[0]) <= tol && std::abs(d[1]) <= tol && std::abs(d[2]) <= tol) ? 1 : 0;
  }
  return static_cast<double>(same) / static_cast<double>(f.pixels.size());
}

struct Best {
  double value = 0;
  void add(double v) { value = std::max(value, v); }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"arpsim against Mesa's llvmpipe: host rendering and the per-pixel path, side by side"};
  int reps = 3;
  double min_s = 0.5;
  std::string md_path, csv_path;
  app.add_option("--repeat", reps, "interleaved repetitions; each figure is the best")->check(CLI::Range(1, 100));
  app.add_option("--min-time", min_s, "seconds each measurement runs at least")->check(CLI::Range(0.01, 60.0));
  std::string only = "all";
  app.add_option("--only", only, "measure only the host render (cube) or the per-pixel path (pixel)")
      ->check(CLI::IsMember({"all", "cube", "pixel"}));
  app.add_option("--md", md_path, "also write the table as Markdown");
  app.add_option("--csv", csv_path, "also write the figures as CSV");
  CLI11_PARSE(app, argc, argv);

  try {
    for (const std::string& out : {md_path, csv_path})  // a missing folder is found now, not after the run
      if (!out.empty()) temp_path_beside(out);
    // --- inputs, shared by both sides -----------------------------------
    const host::Scene gallery = host::make_gallery();
    const glm::dvec3 eye = host::gallery_walk().front();
    const double t_render = 0.5;
    dp::ArpConfig cfg;
    dp::MemoryFormat fmt(cfg.memory);
    const dp::OrientationStream head = bench::turning_head();
    // One memory written, or all four (memory m at depth code 0x8000 + 256 m: memory 0 is nearest, and the
    // codes differ in their high byte, which is what the RGBA8 texel keeps).
    std::map<int, std::unique_ptr<dp::DisplayMemorySet>> mems;
    const auto pattern = host::make_calibration_pattern(cfg.memory.face_size);
    for (int filled : {1, 4}) {
      auto& m = mems[filled] = std::make_unique<dp::DisplayMemorySet>(cfg.memory, cfg.timing.eyes);
      for (int k = 0; k < filled; ++k) host::load_into_memories(*m, k, pattern, 0x8000u + 256u * static_cast<uint32_t>(k));
    }
    std::map<bool, std::unique_ptr<FunctionalModel>> models;
    for (bool bilinear : {false, true}) {
      dp::ArpConfig c = cfg;
      c.pipeline.aa = bilinear ? dp::AaMode::Bilinear : dp::AaMode::Off;
      models[bilinear] = std::make_unique<FunctionalModel>(c);
    }
    const double px_per_frame =
        static_cast<double>(cfg.timing.h_active) * cfg.timing.v_active * cfg.timing.eyes;

    struct PerPixelKey {
      bool bilinear;
      int memories, threads;
      bool operator<(const PerPixelKey& o) const {
        return std::tie(bilinear, memories, threads) < std::tie(o.bilinear, o.memories, o.threads);
      }
    };
    Best stream[3], arp_cube[3], arp_faces[3];  // by arpsim threads
    Best core_hz;  // the fastest the clock was seen: cycles from it are an upper bound
    bool clock_consistent = true;
    std::map<int, Best> gl_cube, gl_faces;       // by LP_NUM_THREADS
    std::map<PerPixelKey, Best> arp_px, gl_px8, gl_px16;
    std::map<PerPixelKey, double> agree_px;      // GL RGBA16 against arpsim
    double agree_cube = 0;
    int64_t triangles = 0;
    std::string renderer;

    std::vector<double> sa(bench::kStreamDoubles, 1.0), sb(bench::kStreamDoubles, 2.0);
    host::CubeFaceRenderer soft;
    dp::DisplayMemoryBank soft_bank(fmt), gl_bank(fmt);
    std::vector<host::FaceImage> soft_visible, gl_visible, faces;
    HmdFrame frame;
    std::vector<uint32_t> rgba;
    ProgressLine progress("arp_versus_llvmpipe", true, int64_t{reps} * 4);  // per repetition: arpsim, llvmpipe x 3
    const bool cube = only != "pixel", pixel = only != "cube";
    for (int r = 0; r < reps; ++r) {
      // STREAM, arpsim's renderer (one thread: it has no other), arpsim's functional model.
      for (int th : {1, 2}) {
        int64_t bytes = 0;
        const double calls = rate([&] { bytes = bench::stream_copy(sa, sb, th); }, min_s);
        stream[th].add(calls * static_cast<double>(bytes));
      }
      if (const auto c = bench::measure_core_clock()) {
        core_hz.add(c->hz());
        clock_consistent = clock_consistent && c->consistent();
      } else {
        clock_consistent = false;
      }
      host::RenderStats st;
      for (int th : {1, 2}) {
        if (!cube) continue;
        soft.set_threads(th);
        arp_cube[th].add(rate([&] { st = soft.render(gallery, {}, t_render, eye, soft_bank); }, min_s));
        arp_faces[th].add(rate([&] { soft.render_faces(gallery, {}, t_render, eye, fmt.face_size, faces); }, min_s));
      }
      triangles = st.triangles;
      for (bool bilinear : {false, true})
        for (int filled : {1, 4})
          for (int th : {1, 2}) {
            if (!pixel) continue;
            RenderOptions ro;
            ro.threads = th;
            arp_px[{bilinear, filled, th}].add(
                px_per_frame * rate([&] { models[bilinear]->render(*mems[filled], head, 0, frame, ro); }, min_s));
          }
      progress.step("repetition " + std::to_string(r + 1) + ": arpsim");
      // llvmpipe with 0, 1 and 2 rasteriser threads: a fresh display each (it reads LP_NUM_THREADS when it
      // starts). 0: everything on the calling thread (one core, against arpsim's one thread); 1: a rasteriser
      // beside the calling thread, which transforms and bins (two cores); 2: two rasterisers.
      for (int th : {0, 1, 2}) {
        host::EglOptions eo;
        eo.software = true;
        eo.threads = th;
        host::GlCubeRenderer gl(host::DepthCode{}, host::LightModel{}, eo);
        gl.set_threads(th == 0 ? 1 : 2);  // its store into the memory: one core, or two
        renderer = gl.context().renderer() + ", OpenGL " + gl.context().version();
        if (!gl.context().is_llvmpipe()) throw std::runtime_error("not llvmpipe: " + renderer);
        if (cube) {
          gl_cube[th].add(rate([&] { gl.render(gallery, {}, t_render, eye, gl_bank); }, min_s));
          gl_faces[th].add(rate([&] { gl.draw(gallery, {}, t_render, eye, fmt.face_size, fmt.depth_bits); }, min_s));
        }
        if (cube && r == 0 && th == 0) {
          soft.render(gallery, {}, t_render, eye, soft_bank, &soft_visible);
          gl.render(gallery, {}, t_render, eye, gl_bank, &gl_visible);
          agree_cube = same_object(soft_visible, gl_visible);
        }
        const int arp_threads = th == 0 ? 1 : th == 2 ? 2 : 0;  // the per-pixel rows: one core, two cores
        for (bool bilinear : {false, true})
          for (int filled : {1, 4})
            for (bool wide : {false, true}) {
              if (!pixel || arp_threads == 0) continue;
              bench::GlPerPixel pp(*models[bilinear], *mems[filled], {filled, bilinear, wide});
              const double v = px_per_frame * rate([&] { pp.render(head, 0, rgba); }, min_s);
              (wide ? gl_px16 : gl_px8)[{bilinear, filled, arp_threads}].add(v);
              if (r == 0 && wide) {
                models[bilinear]->render(*mems[filled], head, 0, frame, {});
                agree_px[{bilinear, filled, arp_threads}] = same_colour(frame, rgba, bilinear ? 2 : 0);
              }
            }
        progress.step("repetition " + std::to_string(r + 1) + ": llvmpipe, LP_NUM_THREADS=" + std::to_string(th));
      }
    }
    const double bw = std::max(stream[1].value, stream[2].value);
    const double bound = bw / bench::kCompulsoryBytesPerPixel;

    std::ostringstream md, csv;
    char line[512];
    md << "Machine: " << cpu_name() << ", " << std::thread::hardware_concurrency() << " hardware threads; "
       << renderer << ". Best of " << reps << " interleaved repetitions of at least " << min_s << " s each.\n"
       << "STREAM copy: " << stream[1].value * 1e-9 << " GB/s on 1 thread, " << stream[2].value * 1e-9
       << " GB/s on 2; the per-pixel bound at " << bench::kCompulsoryBytesPerPixel << " B/pixel: " << bound * 1e-6
       << " M pixels/s.\n";
    const bool cycles = clock_consistent && core_hz.value > 0;
    if (cycles)
      md << "Core clock (chains of dependent adds and multiplies, the fastest of the repetitions): "
         << core_hz.value * 1e-9 << " GHz.\n";
    else
      md << "Core clock: not measured or its two chains disagreed; no cycle figures.\n";
    md << "\n";
    csv << "work,lp_num_threads_or_threads,arpsim,llvmpipe_rgba8,llvmpipe_rgba16,unit,agreement,arpsim_of_stream_bound,"
           "arpsim_cycles_per_pixel\n";
    md << "| work | threads | arpsim | llvmpipe | arpsim / llvmpipe | llvmpipe, 64-bit texel | arpsim / it | agreement | "
          "arpsim of STREAM bound |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    // One core: arpsim on 1 thread, llvmpipe with no rasteriser thread; two cores: arpsim on 2, llvmpipe with
    // one rasteriser beside the binning thread, or two.
    const char* lp_label[3] = {"1; LP_NUM_THREADS=0", "2; LP_NUM_THREADS=1", "2; LP_NUM_THREADS=2"};
    for (int into_memory : {1, 0})
      for (int th : {0, 1, 2}) {
        if (!cube) continue;
        const int at = th == 0 ? 1 : 2;
        const double a = into_memory ? arp_cube[at].value : arp_faces[at].value;
        const double g = into_memory ? gl_cube[th].value : gl_faces[th].value;
        std::snprintf(line, sizeof line,
                      "| gallery cube (%lld triangles, 6 x 512^2), %s | %s | %.1f cubes/s | %.1f cubes/s | "
                      "**%.2f** | | | %s | |\n",
                      static_cast<long long>(triangles),
                      into_memory ? "into the display memory" : "into face images, no memory write", lp_label[th], a, g,
                      a / g, into_memory && th == 0 ? (std::to_string(100.0 * agree_cube).substr(0, 5) + " % same object").c_str() : "");
        md << line;
        std::snprintf(line, sizeof line, "gallery_cube_%s,%d,%.4g,%.4g,,cubes/s,%s,,\n", into_memory ? "memory" : "faces",
                      th, a, g, into_memory && th == 0 ? std::to_string(agree_cube).c_str() : "");
        csv << line;
      }
    for (bool bilinear : {false, true})
      for (int filled : {1, 4})
        for (int th : {1, 2}) {
          if (!pixel) continue;
          const PerPixelKey k{bilinear, filled, th};
          const double a = arp_px[k].value, g8 = gl_px8[k].value, g16 = gl_px16[k].value;
          const double cyc = cycles && th == 1 ? core_hz.value / a : 0;  // one thread: its cycles alone
          char cyc_md[48] = "";
          if (cyc > 0) std::snprintf(cyc_md, sizeof cyc_md, " (%.1f cycles/px)", cyc);
          std::snprintf(line, sizeof line,
                        "| per-pixel, %s, %s | %d (LP_NUM_THREADS=%d) | %.0f M px/s%s | %.0f M | **%.2f** | %.0f M | %.2f | %.1f %% same colour%s | "
                        "%.0f %% |\n",
                        bilinear ? "bilinear" : "nearest", filled == 1 ? "1 memory" : "4 memories full", th,
                        th == 1 ? 0 : 2, a * 1e-6, cyc_md,
                        g8 * 1e-6, a / g8, g16 * 1e-6, a / g16, 100.0 * agree_px[k], bilinear ? " (within 2)" : "",
                        100.0 * a / bound);
          md << line;
          std::snprintf(line, sizeof line, "per_pixel_%s_%dmem,%d,%.4g,%.4g,%.4g,pixels/s,%.4f,%.4f,%s\n",
                        bilinear ? "bilinear" : "nearest", filled, th, a, g8, g16, agree_px[k], a / bound,
                        cyc > 0 ? std::to_string(cyc).c_str() : "");
          csv << line;
        }
    std::fputs(md.str().c_str(), stdout);
    if (!md_path.empty()) write_text_atomic(md_path, md.str());
    if (!csv_path.empty()) write_text_atomic(csv_path, csv.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "\narp_versus_llvmpipe: %s\n", e.what());
    return 1;
  }
  return 0;
}
