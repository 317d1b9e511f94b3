// arpsim tradeoff: the speed-accuracy trade measured in one table. The whole
// sweep locally (points as separate `arpsim tradeoff --point` processes on
// the machine's cores), one point, the merge, or the sweep written out as a
// Slurm job array. The work is sim/TradePoints, TradeMeasure, TradeTable,
// SweepRunner; this file parses and prints.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <thread>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"
#include "common/InputFile.hpp"
#include "common/Interrupt.hpp"
#include "common/OutputPaths.hpp"
#include "sim/SweepRunner.hpp"
#include "sim/TradeMeasure.hpp"
#include "sim/TradeTable.hpp"

namespace arp::app {

namespace {
namespace fs = std::filesystem;

struct TradeoffArgs {
  std::string out, point, doc;
  std::vector<std::string> emit;
  bool quick = false, merge = false, plan_only = false, list = false, quiet = false;
  int jobs = 0;
  int slurm_minutes = 0;  // 0: SlurmSweep's default
};

std::string today() {
  const std::time_t now = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%d", std::gmtime(&now));
  return b;
}

std::string self_path() { return fs::read_symlink("/proc/self/exe").string(); }
int merge(const TradeoffArgs& a, const sim::TradePlan& plan, int failed, double sweep_s = 0, int jobs = 0) {
  sim::TradeTables t = sim::collect_trade_results(a.out, plan);
  t.sweep_wall_s = sweep_s;
  t.sweep_jobs = jobs;
  for (const auto& n : sim::write_trade_outputs(a.out, t, today())) std::printf("note: %s\n", n.c_str());
  if (!a.doc.empty()) {
    const std::string doc = read_input_file(a.doc, 1 << 22, "doc");
    write_text_atomic(a.doc, sim::update_trade_doc(doc, sim::trade_markdown(t, today()), a.doc));
    std::printf("updated %s\n", a.doc.c_str());
  }
  std::printf("%zu of %zu points measured; tables in %s/tradeoff.md (CSV, JSON and plots beside it)\n", t.results.size(),
              plan.points.size(), a.out.c_str());
  if (!t.missing.empty() || failed) {
    std::fprintf(stderr, "arpsim: %zu points missing (listed in tradeoff.md; logs in %s/points/)\n", t.missing.size(), a.out.c_str());
    return 1;
  }
  return 0;
}

int run_tradeoff(TradeoffArgs& a) {
  if (a.list) {
    for (const auto& p : sim::trade_points(sim::TradeScale{a.quick}))
      std::printf("%-40s %-8s %s\n", p.id.c_str(), sim::trade_kind_key(p.kind), p.exclusive() ? "alone (measures speed)" : "");
    return 0;
  }
  if (a.out.empty()) throw InputError("--out", "", "required: the folder the points and tables go to");
  const int modes = !a.point.empty() + a.merge + !a.emit.empty() + a.plan_only;
  if (modes > 1) throw InputError("--point", "", "--point, --merge, --emit and --plan-only each do one thing: give one");
  if (!a.doc.empty() && (!a.point.empty() || !a.emit.empty() || a.plan_only))
    throw InputError("--doc", a.doc, "only a sweep or --merge writes the tables");
  if (!a.doc.empty()) sim::update_trade_doc(read_input_file(a.doc, 1 << 22, "doc"), "", a.doc);  // its markers, before hours of work
  if (a.slurm_minutes > 0 && a.emit.empty()) throw InputError("--slurm-time", "", "only with --emit slurm DIR");
  if (!a.emit.empty()) sim::check_slurm_sweep_paths(a.emit[0], a.emit[1], fs::absolute(a.out).string());
  if (!a.point.empty()) {  // one point: what every local process and every array task runs
    const sim::TradePlan plan = sim::read_trade_plan(a.out);
    const sim::TradePoint& p = sim::find_trade_point(plan.points, a.point);
    auto progress = std::make_shared<ProgressLine>(p.id, !a.quiet);
    const auto r = sim::measure_trade_point(p, plan.scale, (fs::path(a.out) / "points" / (p.id + ".scratch")).string(),
                                            [progress](double f, const std::string& w) { progress->update(f, w); });
    auto result = r;
    result["run"] = plan.run_id;
    write_text_atomic(sim::trade_result_path(a.out, p.id), result.dump(1) + "\n");
    return 0;
  }
  if (a.merge) return merge(a, sim::read_trade_plan(a.out), 0);
  make_output_folder("--out", (fs::path(a.out) / "points").string());
  sim::TradePlan plan = sim::make_trade_plan(sim::TradeScale{a.quick});
  plan.run_id = sim::new_trade_run_id();
  sim::clear_trade_results(a.out, plan);  // no figure of an earlier sweep survives into this one
  sim::write_trade_plan(a.out, plan);
  const std::string out_abs = fs::absolute(a.out).string();
  if (!a.emit.empty()) {
    sim::SlurmSweep s = sim::trade_slurm_sweep(plan, out_abs, self_path());
    if (a.slurm_minutes > 0) s.task_minutes = a.slurm_minutes;
    for (const auto& f : sim::write_slurm_sweep(a.emit[1], s)) std::printf("written %s\n", f.c_str());
    std::printf("submit with: %s/submit.sh   (plan: %s/plan.json, %zu points)\n", a.emit[1].c_str(), a.out.c_str(), plan.points.size());
    return 0;
  }
  if (a.plan_only) {
    std::printf("written %s/plan.json (%zu points)\n", a.out.c_str(), plan.points.size());
    return 0;
  }
  const std::vector<sim::SweepCommand> cmds = sim::trade_sweep_commands(plan, out_abs, self_path());
  const InterruptGuard ctrl_c;  // Ctrl-C / SIGTERM: the running points are stopped, the finished ones merged
  ProgressLine progress("tradeoff", !a.quiet);
  const auto t0 = std::chrono::steady_clock::now();
  const int jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const sim::SweepOutcome o = sim::run_sweep_locally(cmds, jobs, [&](double f, const std::string& w) { progress.update(f, w); },
                                                     interrupt_signal);
  progress.finish();
  int failed = 0;
  for (const auto& [id, st] : o.exit_status)
    if (st != 0) {
      ++failed;
      std::fprintf(stderr, "arpsim: point %s failed (exit %d): see %s\n", id.c_str(), st, sim::trade_log_path(a.out, id).c_str());
    }
  const double sweep_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("sweep: %zu points in %.0f s on %d cores\n", o.exit_status.size(), sweep_s, jobs);
  const int rc = merge(a, plan, failed, sweep_s, jobs);
  return o.stop_signal ? interrupted_exit_status(o.stop_signal) : rc;
}
}  // namespace

Runner add_tradeoff_command(CLI::App& app) {
  auto a = std::make_shared<TradeoffArgs>();
  CLI::App* cmd = app.add_subcommand("tradeoff", "Measure the speed-accuracy trade: levels, widths, theta_t, regions, latency knobs");
  cmd->add_option("--out", a->out, "Folder for the plan, the points' results and the tables")->check(output_name("folder"));
  cmd->add_flag("--quick", a->quick, "A smaller sweep (minutes): fewer frames and points");
  cmd->add_option("--jobs,-j", a->jobs, "Points run side by side (default: the cores; speed points always run alone)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--point", a->point, "Measure only this point (ids: --list) into OUT/points/ID.json");
  cmd->add_flag("--merge", a->merge, "Only merge the results in OUT into the tables");
  cmd->add_flag("--plan-only", a->plan_only, "Only write OUT/plan.json");
  cmd->add_option("--emit", a->emit, "Write the sweep as a job array: --emit slurm DIR")  // (the kind: sim::check_slurm_sweep_paths)
      ->expected(2)->check(output_name("folder").application_index(1));
  cmd->add_option("--slurm-time", a->slurm_minutes,
                  "--emit slurm: the wall-clock limit of each point's task, minutes (default 60; the full sweep's longest point "
                  "takes about a minute on 2 cores)")
      ->check(CLI::Range(1, 10080));
  cmd->add_option("--doc", a->doc, "Also replace the generated block of this markdown file with the tables")->check(output_name());
  cmd->add_flag("--list", a->list, "List the points (with --quick: the quick sweep's)");
  add_quiet_flag(*cmd, a->quiet);
  return [a] { return run_tradeoff(*a); };
}

}  // namespace arp::app
