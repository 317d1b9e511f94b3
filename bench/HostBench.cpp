// The host's own speed (our code, not the simulated engine): the cube-face
// renderer on the gallery -- triangles submitted and texels filled per wall
// second for one eye's full six-face render, on 1 and 2 threads, into float
// faces and into a display memory -- and the priority scheduler's
// cost per frame as the object count grows (1 k, 10 k, 100 k objects).
#include <benchmark/benchmark.h>

#include <memory>
#include <random>

#include "host/priority/PriorityScheduler.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/Primitives.hpp"

namespace {

using namespace arp;
using namespace arp::host;

void BM_RenderGalleryCube(benchmark::State& state) {
  static const Scene g = make_gallery();
  const int S = static_cast<int>(state.range(0));
  CubeFaceRenderer r;
  r.set_threads(static_cast<int>(state.range(1)));
  std::vector<FaceImage> faces;
  RenderStats last;
  for (auto _ : state) {
    last = r.render_faces(g, {}, 0.5, gallery_walk().front(), S, faces);
    benchmark::DoNotOptimize(faces.data());
  }
  state.counters["triangles_per_s"] =
      benchmark::Counter(static_cast<double>(last.triangles) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["texels_filled_per_s"] =
      benchmark::Counter(static_cast<double>(last.texels_filled) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(last.triangles);
}
BENCHMARK(BM_RenderGalleryCube)->ArgNames({"face", "threads"})->ArgsProduct({{256, 512}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

// The same render ending where the run needs it: colour and depth codes in a display memory's back buffer.
void BM_RenderGalleryIntoMemory(benchmark::State& state) {
  static const Scene g = make_gallery();
  dp::MemoryConfig mc;
  mc.face_size = static_cast<int>(state.range(0));
  dp::DisplayMemoryBank bank{dp::MemoryFormat(mc)};
  CubeFaceRenderer r;
  r.set_threads(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    r.render(g, {}, 0.5, gallery_walk().front(), bank);
    benchmark::DoNotOptimize(bank.read_back(0, 0, 0));
  }
}
BENCHMARK(BM_RenderGalleryIntoMemory)->ArgNames({"face", "threads"})->ArgsProduct({{512}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SchedulerAssign(benchmark::State& state) {
  const size_t n = static_cast<size_t>(state.range(0));
  Scene s;
  auto ball = std::make_shared<Mesh>(make_sphere(0.2, 6));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-200, 200);
  for (size_t i = 0; i < n; ++i) {
    SceneObject& o = add_object(s, "o", ball, {u(rng), 1, u(rng)}, {});
    if (i % 7 == 0) o.animation.spin_deg_per_s = 30;
  }
  PriorityConfig pc;
  PriorityScheduler sch(s, pc, 512);
  double t = 0;
  for (auto _ : state) {
    sch.assign({t, 1.6, 0}, 1.0, {}, t);
    t += 1.0 / 60;
  }
  state.counters["objects_per_s"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SchedulerAssign)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
