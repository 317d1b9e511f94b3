// arpsim run: a head-motion trace replayed through the pipeline, frame after
// frame, at the functional (bit-accurate, untimed) level: each pixel's
// orientation is the trace sample the latch policy puts in the register.
// Writes the frames as images and a JSON report.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "FrameImage.hpp"
#include "apps/config/ConfigFile.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "common/InputError.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::app {

namespace {

struct RunArgs {
  ConfigOptions cfg;
  CubeMapOptions cubemap;
  std::string trace, out_dir = "run", report;
  int64_t frames = 60, first = 0, every = 1;
  int threads = 0;
  bool quiet = false;
};

int run(const RunArgs& a) {
  const dp::ArpConfig c = a.cfg.resolve();
  if (a.frames < 1 || a.frames > 1'000'000) throw InputError("--frames", "", "must be 1 .. 1000000");
  if (a.first < 0) throw InputError("--first-frame", "", "must be >= 0");
  if (a.every < 0) throw InputError("--every", "", "must be >= 0 (0: no images)");
  const auto trace = tracker::read_trace_csv(a.trace);
  std::vector<dp::OrientationSample> samples;
  samples.reserve(trace.size());
  for (const auto& p : trace)
    samples.push_back({p.time_ps, dp::Quat{p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}});
  const dp::OrientationStream stream(std::move(samples), a.trace);

  const FunctionalModel model(c);
  std::string source;
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  host::load_into_memories(mem, 0, a.cubemap.load(c.memory.face_size, source), host::far_depth(mem.format()));
  std::error_code ec;
  if (a.every > 0) {
    std::filesystem::create_directories(a.out_dir, ec);
    if (ec || !std::filesystem::is_directory(a.out_dir))
      throw InputError(a.out_dir, "", "cannot create the output folder" + (ec ? ": " + ec.message() : std::string()));
  }

  const auto& t = model.timing();
  const int64_t lead = c.pipeline.latch_lead_cycles;
  const int64_t end_ps = t.cycles_to_ps(t.frame_start_cycle(a.first + a.frames));
  nlohmann::json frames = nlohmann::json::array();
  HmdFrame f;
  RenderOptions ro;
  ro.threads = a.threads;
  int images = 0;
  ProgressLine progress("run", !a.quiet);
  for (int64_t k = 0; k < a.frames; ++k) {
    const int64_t frame = a.first + k;
    model.render(mem, stream, frame, f, ro);
    if (a.every > 0 && k % a.every == 0) {
      char name[64];
      std::snprintf(name, sizeof name, "frame_%06lld.png", static_cast<long long>(frame));
      host::write_rgb8((std::filesystem::path(a.out_dir) / name).string(), frame_to_image(f));
      ++images;
    }
    const size_t lo = stream.index_at(t.cycles_to_ps(t.frame_start_cycle(frame) - lead));
    const size_t hi = stream.index_at(t.cycles_to_ps(t.frame_start_cycle(frame + 1) - lead));
    frames.push_back({{"frame", frame},
                      {"start_ps", t.cycles_to_ps(t.frame_start_cycle(frame))},
                      {"first_sample", lo},
                      {"last_sample", hi}});
    progress.update(static_cast<double>(k + 1) / static_cast<double>(a.frames),
                    "frame " + std::to_string(k + 1) + "/" + std::to_string(a.frames));
  }
  std::printf("arpsim run: %lld frames (%lld..%lld) of %s with %s, %d images in %s\n",
              static_cast<long long>(a.frames), static_cast<long long>(a.first),
              static_cast<long long>(a.first + a.frames - 1), a.trace.c_str(), source.c_str(), images,
              a.every > 0 ? a.out_dir.c_str() : "(none)");
  if (trace.back().time_ps < end_ps)
    std::printf("  note: the trace ends at %.6f s; later pixels hold its last sample (sample-and-hold)\n",
                static_cast<double>(trace.back().time_ps) * 1e-12);
  if (!a.report.empty()) {
    nlohmann::json r{{"trace", a.trace},     {"samples", trace.size()}, {"cube_map", source},
                     {"frames", frames},     {"images", images},        {"out_dir", a.out_dir},
                     {"config", config::to_json(c)}};
    write_text_atomic(a.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace

Runner add_run_command(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Replay a head-motion trace through the pipeline, frame by frame");
  a->cfg.add_to(*cmd);
  a->cubemap.add_to(*cmd);
  cmd->add_option("--trace", a->trace, "Trace file (CSV, docs/tracker.md); e.g. from arpsim tracker synth")->required();
  cmd->add_option("--frames", a->frames, "Number of frames")->capture_default_str();
  cmd->add_option("--first-frame", a->first, "Index of the first frame (sets its time)")->capture_default_str();
  cmd->add_option("--out-dir", a->out_dir, "Folder for frame_NNNNNN.png (created if missing)")->capture_default_str();
  cmd->add_option("--every", a->every, "Write every Nth frame as an image (0: none)")->capture_default_str();
  cmd->add_option("--threads", a->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 256));
  cmd->add_option("--report", a->report, "Also write a JSON report (which trace samples each frame used)");
  cmd->add_flag("--quiet,-q", a->quiet, "No progress line");
  return [a] { return run(*a); };
}

}  // namespace arp::app
