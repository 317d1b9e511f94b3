// Renders N default stereo frames with the functional model and nothing else,
// for counting cycles with perf (bench/cycles-per-pixel.sh): on a shared
// machine whose clock and neighbours vary, cycles per pixel are steadier
// than wall-clock rates. Where perf has no cycle counter, the loop's wall time
// and the core's clock measured just before and after it (bench/CoreClock.hpp)
// give the cycles instead; both are printed.
// Usage: arp_frame_loop BILINEAR(0|1) THREADS MEMORIES_FILLED FRAMES
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "CoreClock.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

int main(int argc, char** argv) {
  using namespace arp;
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s BILINEAR(0|1) THREADS MEMORIES_FILLED(1..4) FRAMES\n", argv[0]);
    return 2;
  }
  const bool bilinear = std::atoi(argv[1]) != 0;
  const int threads = std::atoi(argv[2]), filled = std::atoi(argv[3]), frames = std::atoi(argv[4]);
  if (threads < 1 || filled < 1 || filled > 4 || frames < 0) {
    std::fprintf(stderr, "%s: threads >= 1, memories 1..4, frames >= 0\n", argv[0]);
    return 2;
  }
  dp::ArpConfig c;
  c.pipeline.aa = bilinear ? dp::AaMode::Bilinear : dp::AaMode::Off;
  const FunctionalModel model(c);
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  const auto cm = host::make_calibration_pattern(c.memory.face_size);
  for (int m = 0; m < filled; ++m)
    host::load_into_memories(mem, m, cm, host::far_depth(mem.format()) - static_cast<uint32_t>(m));
  std::vector<dp::OrientationSample> s;  // 200 deg/s, 1 kHz samples
  for (int i = 0; i <= 40; ++i)
    s.push_back({int64_t{i} * 1'000'000'000, dp::from_yaw_pitch_roll_deg(20.0 + 0.2 * i, 10.0, 5.0)});
  const dp::OrientationStream o(s, "frame loop");
  HmdFrame f;
  RenderOptions ro;
  ro.threads = threads;
  const auto before = bench::measure_core_clock();
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) model.render(mem, o, 0, f, ro);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto after = bench::measure_core_clock();
  std::printf("%d frames of %zu pixels in %.6f s\n", frames, f.pixels.size(), secs);
  std::printf("core clock before: %s; after: %s\n", bench::describe(before).c_str(), bench::describe(after).c_str());
  // The faster of the two clocks: the larger cycle count, an upper bound (bench/CoreClock.hpp).
  if (frames > 0 && before && after && before->consistent() && after->consistent())
    std::printf("cycles per pixel, %d thread(s) together, from the clock: %.2f\n", threads,
                secs * threads * std::max(before->hz(), after->hz()) / (static_cast<double>(frames) * f.pixels.size()));
  return 0;
}
