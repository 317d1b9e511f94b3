// arpsim plan: a configuration sized for a scene and its motion (sim/Planner),
// written as a configuration file every command accepts, with plan.md beside it.
#include <cstdio>
#include <filesystem>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "MotionOptions.hpp"
#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"
#include "common/PrintfText.hpp"
#include "common/OutputPaths.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "sim/Planner.hpp"

namespace arp::app {

namespace {

struct PlanArgs {
  ConfigOptions cfg;
  sim::PlanRequest req;
  std::string out = "plan.json";
  bool quiet = false;
};

int run_plan(PlanArgs& a) {
  sim::PlanRequest& r = a.req;
  r.base = a.cfg.resolve();
  r.base_source = (a.cfg.file.empty() ? std::string("the default configuration") : a.cfg.file) + (a.cfg.sets.empty() ? "" : " with --set");
  if (a.out.empty()) throw InputError("--out", "", "is empty: name the configuration file to write (its .md and .tiles.png go beside it)");
  const std::string md = std::filesystem::path(a.out).replace_extension(".md").string();
  const std::string tiles = std::filesystem::path(a.out).replace_extension(".tiles.png").string();
  check_output_paths({{"--out", a.out}, {"--out's account", md}, {"--out's tile picture", tiles}},
                     [&] {
                       std::vector<NamedPath> in = r.memories.input_files();
                       in.push_back({"--config", a.cfg.file});
                       in.push_back({"--walk", r.walk == "gallery" ? "" : r.walk});
                       in.push_back({"--trace", r.head.trace});
                       return in;
                     }());
  ProgressLine progress("plan", !a.quiet);
  r.progress = [&](int step, int steps, double f, const std::string& w) { progress.update_step(step, steps, f, w); };
  const sim::Plan p = sim::make_plan(r);
  progress.update(1.0, "planned");
  for (const std::string& w : p.warnings) std::fprintf(stderr, "arpsim plan: warning: %s\n", w.c_str());
  const std::string text = sim::plan_markdown(p, r);
  // The three together or none: a failure leaves no new plan beside an old picture, nor a picture of no plan.
  OutputGroup outputs;
  host::write_rgb8_file(outputs.stage(tiles), sim::plan_tiles_image(p), tiles);
  write_text_file(outputs.stage(md), text, md);
  write_text_file(outputs.stage(a.out), sim::plan_config_text(p), a.out);
  outputs.commit();
  std::printf("%s\narpsim plan: %s, %s and %s (the tiles each memory can be drawn on) written; run with --config %s\n", text.c_str(),
              a.out.c_str(), md.c_str(), tiles.c_str(), a.out.c_str());
  return 0;
}

}  // namespace

Runner add_plan_command(CLI::App& app) {
  auto a = std::make_shared<PlanArgs>();
  CLI::App* cmd = a->cfg.add_command(
      app, "plan", "Size a configuration for a scene and its motion: face size, datapath widths, display memories (docs/planning.md)");
  // Only the scene: the plan is made for a walk, not for a cube map, a position or a renderer.
  cmd->add_option("--scene", a->req.memories.scene, "The scene to plan for: a scene file (docs/host.md) or 'gallery'")->required();
  add_walk_options(*cmd, a->req.walk, a->req.walk_speed, a->req.threshold_deg);
  // The head's own turning on the walk, as `run` takes it: the priority rule sees the eyes move as the head turns.
  add_motion_options(*cmd, a->req.head.motion, false);
  cmd->add_option("--trace", a->req.head.trace,
                  "A recorded head motion on top of the walk (CSV, docs/tracker.md), from the walk's start; standing (--speed 0) "
                  "the plan covers the trace to its last sample");
  cmd->add_option("--ipd", a->req.memories.ipd_m,
                  "Distance between the eyes, metres, as run's --ipd: how far turning moves them, and where they see from; default " +
                      printf_text("%g", dp::kDefaultIpdM));
  auto* texel_error = cmd->add_option("--texel-error", a->req.texel_error,
                                      "Bound on the datapath's texel-position error, texels (0: what the starting configuration measures)")
                          ->capture_default_str();
  cmd->add_option("--resolve", a->req.resolve,
                  "The display pixel a face's largest texel is held to: at the lens centre, or the finest (a corner)")
      ->check(CLI::IsMember({"centre", "finest"}))
      ->capture_default_str();
  cmd->add_option("--load-tolerance", a->req.load_tolerance,
                  "A display memory more must cut the host's load by more than this share of the least load")
      ->capture_default_str();
  cmd->add_option("--fill-points", a->req.fill_points,
                  "Points of the motion where each object's fill is measured by rendering the scene, 2 .. " +
                      std::to_string(arp::sim::kMaxSamples) +
                      " (the samples between interpolate; more follow the fill's peaks the engine replay needs, at a render each)")
      ->capture_default_str();
  cmd->add_option_function<double>(
      "--memory-limit", [a](double v) { a->req.memory_limit_mib = v; },
      "The most hardware display memory a ladder of memories may take, MiB, as whole faces or, where those are over it, "
      "tile-sparse as it would be planned (with its tile pools: --weigh-pools) (default: the starting configuration's, or the least any ladder takes at the "
      "planned face size where that is more; 0: no limit)");
  cmd->add_option_function<double>(
      "--depth-error", [a](double v) { a->req.depth_error = v; },
      "With several memories: the share of the texels two or more memories hold that the depth code may compose from the "
      "wrong memory (default: what the starting configuration's width measures)");
  cmd->add_flag_function("--keep-widths", [a](int64_t) { a->req.size_widths = false; },
                "Keep the starting configuration's datapath widths (no accuracy-harness search)")
      ->excludes(texel_error);  // (a bound no search is made for would be silently ignored)
  auto* objects_only = cmd->add_flag_function("--objects-only", [a](int64_t) { a->req.weigh_regions = false; },
                                              "Keep object-level priority rendering: do not weigh region priority rendering "
                                              "(memory.region_size_m 0)");
  cmd->add_flag_function("--take-regions", [a](int64_t) { a->req.take_regions = true; },
                         "Take region priority rendering where it keeps objects within theta_t as well as objects do and renders "
                         "less (by default it is weighed and reported only: its tearing between regions is not bounded)")
      ->excludes(objects_only);
  auto* whole = cmd->add_flag_function("--whole-faces", [a](int64_t) { a->req.tile_sparse = false; },
                "Keep every tile of the faces present (no memory.tiles, no memory.tile_pool: a display memory without a tile "
                "table); by default the memories hold only the tiles the motion can draw on, or a tile pool, where that takes "
                "less memory");
  auto* fixed = cmd->add_flag_function("--fixed-tiles", [a](int64_t) { a->req.tile_pool = false; },
                         "Hold the tiles the motion can draw on without a tile pool (no memory.tile_pool); by default a memory "
                         "takes a pool of the most tiles it draws on at once where that takes less memory")
      ->excludes(whole);
  cmd->add_flag_function("--weigh-pools", [a](int64_t) { a->req.weigh_pools = true; },
                         "Hold each ladder to --memory-limit with the tile pools it would take (by default with its fixed tiles, "
                         "the pools taken after): deeper ladders fit, rendering less at more error walking (docs/planning.md, "
                         "item 3)")
      ->excludes(whole)
      ->excludes(fixed);
  cmd->add_option("--out,-o", a->out, "The configuration written (its account beside it, .md)")->capture_default_str();
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run_plan(*a); };
}

}  // namespace arp::app
