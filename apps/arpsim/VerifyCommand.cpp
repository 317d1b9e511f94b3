// arpsim verify: the accuracy harness -- datapath against the golden
// reference at any widths -- as a table, optionally a JSON report.
#include <cstdio>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/OutputPaths.hpp"
#include "reference/accuracy/AccuracyHarness.hpp"

namespace arp::app {

namespace {
struct VerifyArgs {
  ConfigOptions cfg;
  accuracy::Options opt;
  bool no_directed = false;
  bool no_aligned = false;
  std::string json;
  bool quiet = false;
};

int run_verify(VerifyArgs& a) {
  const dp::ArpConfig c = a.cfg.resolve();
  check_output_paths({{"--json", a.json}}, {{"--config", a.cfg.file}});  // before the harness's minutes, not after
  a.opt.directed = !a.no_directed;
  a.opt.aligned = !a.no_aligned;
  auto progress = std::make_shared<ProgressLine>("verify", !a.quiet);
  a.opt.progress = [progress](const char* stage, double f) { progress->update(f, stage); };
  const accuracy::Report r = accuracy::run(c, a.opt);
  std::printf("%s", accuracy::to_text(r).c_str());
  if (!a.json.empty()) write_text_atomic(a.json, accuracy::to_json(r) + "\n");
  return 0;
}
}  // namespace

Runner add_verify_command(CLI::App& app) {
  auto a = std::make_shared<VerifyArgs>();
  CLI::App* cmd = a->cfg.add_command(app, "verify", "Compare the bit-accurate datapath with the golden reference");
  cmd->add_option("--frames", a->opt.frame_orientations, "Generic orientations checked at every display pixel")->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--random", a->opt.random_orientations, "Seeded random orientations")->capture_default_str()->check(CLI::Range(0, 100000));
  cmd->add_option("--pixels", a->opt.random_pixels, "Random pixels (and directions) per random orientation")->capture_default_str()
      ->check(CLI::Range(0, 10000000));
  cmd->add_option("--color-frames", a->opt.color_orientations, "Bilinear frames compared colour by colour")->capture_default_str()
      ->check(CLI::Range(0, 100));
  cmd->add_option("--seed", a->opt.seed, "Random seed")->capture_default_str();
  cmd->add_option("--worst", a->opt.worst_kept, "Worst inputs listed")->capture_default_str()->check(CLI::Range(0, 1000));
  cmd->add_flag("--no-directed", a->no_directed, "Skip the directed extreme cases");
  cmd->add_flag("--no-aligned", a->no_aligned,
                "Skip the whole-frame views aligned with the cube axes (straight ahead, 90-degree turns, edge field of view)");
  cmd->add_option("--aligned-step", a->opt.aligned_row_step, "Check every n-th line of the aligned views")
      ->capture_default_str()->check(CLI::Range(1, 8192));
  cmd->add_option("--json", a->json, "Also write the report as JSON")->check(output_name());
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run_verify(*a); };
}

}  // namespace arp::app
