// Functional-model throughput (display pixels per second) on the default
// stereo configuration, nearest and bilinear, 1 and 2 threads, with one or
// all four display memories filled; and in the same run a STREAM-style copy,
// the machine's memory-bandwidth bound. The summary prints each frame
// benchmark's distance to that bound: the model must at least read each
// pixel's lens vector (3 x 4 bytes) and write its colour (4 bytes).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "BenchInputs.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

namespace {

using namespace arp;
using bench::kCompulsoryBytesPerPixel;
using bench::turning_head;

struct Fixture {
  dp::ArpConfig cfg;
  std::unique_ptr<FunctionalModel> model;
  std::unique_ptr<dp::DisplayMemorySet> mem;
  dp::OrientationStream orientation = turning_head();
  HmdFrame frame;
};

Fixture& fixture(bool bilinear, int filled) {
  static std::map<std::pair<bool, int>, std::unique_ptr<Fixture>> cache;
  auto& f = cache[{bilinear, filled}];
  if (!f) {
    f = std::make_unique<Fixture>();
    f->cfg.pipeline.aa = bilinear ? dp::AaMode::Bilinear : dp::AaMode::Off;
    f->cfg.memory.count = std::max(f->cfg.memory.count, filled);  // 8: the composition unit's every input
    f->model = std::make_unique<FunctionalModel>(f->cfg);
    f->mem = std::make_unique<dp::DisplayMemorySet>(f->cfg.memory, f->cfg.timing.eyes);
    const auto cm = host::make_calibration_pattern(f->cfg.memory.face_size);
    for (int m = 0; m < filled; ++m)
      host::load_into_memories(*f->mem, m, cm, host::far_depth(f->mem->format()) - static_cast<uint32_t>(m));
  }
  return *f;
}

void BM_FunctionalFrame(benchmark::State& state) {
  const bool bilinear = state.range(0) != 0;
  const int threads = static_cast<int>(state.range(1));
  const int filled = static_cast<int>(state.range(2));
  Fixture& f = fixture(bilinear, filled);
  RenderOptions ro;
  ro.threads = threads;
  for (auto _ : state) {
    f.model->render(*f.mem, f.orientation, 0, f.frame, ro);
    benchmark::DoNotOptimize(f.frame.pixels.data());
  }
  const double px = static_cast<double>(f.frame.pixels.size());
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * px));
  state.counters["Mpx/s"] = benchmark::Counter(px * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FunctionalFrame)
    ->ArgNames({"bilinear", "threads", "memories_filled"})
    ->ArgsProduct({{0, 1}, {1, 2}, {1, 2, 4, 8}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.5);

// STREAM "copy": a[i] = b[i] over arrays far larger than the caches; bytes
// counted as STREAM does (read + write).
void BM_StreamCopy(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  static std::vector<double> a, b;
  if (a.empty()) {
    a.assign(bench::kStreamDoubles, 1.0);
    b.assign(bench::kStreamDoubles, 2.0);
  }
  int64_t bytes = 0;
  for (auto _ : state) {
    bytes += bench::stream_copy(a, b, threads);
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(bytes);
}
BENCHMARK(BM_StreamCopy)->ArgNames({"threads"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// Collects each benchmark's rate while printing as usual: with repetitions,
// Google Benchmark's median aggregate of the per-repetition rates (it can
// differ from the console's rate at the median time, since repetitions run
// different iteration counts); without, the single run's rate.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.error_occurred) continue;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.run_type != Run::RT_Iteration && !median) continue;
      const std::string name = r.run_name.str();
      for (const char* key : {"items_per_second", "bytes_per_second"}) {
        auto it = r.counters.find(key);
        if (it == r.counters.end()) continue;
        Rates& rates = key[0] == 'i' ? frames[name] : stream[name];
        (median ? rates.median : rates.runs).push_back(it->second.value);
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  struct Rates {
    std::vector<double> runs, median;
    double value() const {
      if (!median.empty()) return median.back();
      std::vector<double> v = runs;
      std::sort(v.begin(), v.end());
      return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
    }
  };
  std::map<std::string, Rates> frames, stream;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SummaryReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  benchmark::Shutdown();
  double stream = 0.0;  // the best thread count's median: the machine's copy bandwidth
  for (const auto& [name, r] : rep.stream) stream = std::max(stream, r.value());
  if (stream > 0.0 && !rep.frames.empty()) {
    const double bound = stream / kCompulsoryBytesPerPixel;
    std::printf("\nmemory-bandwidth bound: STREAM copy %.2f GB/s / %.0f B per pixel = %.0f M pixels/s\n",
                stream * 1e-9, kCompulsoryBytesPerPixel, bound * 1e-6);
    std::printf("%-64s %12s %10s\n", "benchmark (median of repetitions)", "M pixels/s", "of bound");
    for (const auto& [name, r] : rep.frames) {
      const double rate = r.value();
      std::printf("%-64s %12.1f %9.1f%%\n", name.c_str(), rate * 1e-6, 100.0 * rate / bound);
    }
  }
  return 0;
}
