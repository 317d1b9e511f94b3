// The trade table (sim/Trade*, sim/HardwareCost, sim/SweepRunner, `arpsim
// tradeoff`): the cost column matches the synthesis CSV, points are
// standalone processes whose results merge into tables that keep missing
// points as rows, the local runner keeps speed points alone, the Slurm
// scripts have the sweep's shape, and docs/tradeoff.md has the tables'
// current structure.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "TestSupport.hpp"
#include "rtl_model/verilated/VerilatedUnits.hpp"
#include "sim/HardwareCost.hpp"
#include "sim/SweepRunner.hpp"
#include "sim/TradeMeasure.hpp"
#include "sim/TradeTable.hpp"

namespace arp {
namespace {

namespace fs = std::filesystem;
using sim::TradeKind;

std::string slurp(const std::string& path) { return test::read_text(path); }

// docs/hdl-cost.csv read here on its own: (configuration, module) -> cells.
std::map<std::pair<std::string, std::string>, int64_t> csv_cells() {
  std::map<std::pair<std::string, std::string>, int64_t> out;
  std::ifstream in(std::string(ARPSIM_SOURCE_DIR) + "/docs/hdl-cost.csv");
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {  // configuration,module,"parameters",cells,...
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1);
    const auto q2 = line.find('"', line.find('"', c2) + 1);
    if (c1 == std::string::npos || c2 == std::string::npos || q2 == std::string::npos) continue;
    out[{line.substr(0, c1), line.substr(c1 + 1, c2 - c1 - 1)}] = std::stoll(line.substr(q2 + 2));
  }
  return out;
}

TEST(Tradeoff, EveryWidthNamedAfterAnRtlConfigurationIsSynthesizedWithItsParameters) {
  const auto cells = csv_cells();
  std::set<std::string> configurations;
  for (const auto& [k, v] : cells) configurations.insert(k.first);
  ASSERT_GE(configurations.size(), 2u);
  size_t matched = 0;
  for (const auto& p : sim::trade_points(sim::TradeScale{false})) {
    if (p.kind != TradeKind::Width || !configurations.count(p.label)) continue;
    const sim::HardwareCost c = sim::hardware_cost(sim::trade_config(p));
    EXPECT_TRUE(c.fully_synthesized()) << p.id << ": " << c.synthesized.size() << " of the RTL modules matched";
    // The CSV lists a module once per distinct parameter set: a configuration
    // that shares a module's parameters with the default has no row of its own.
    int64_t sum = 0;
    for (const auto& m : sim::rtl_module_keys())
      sum += cells.count({p.label, m}) ? cells.at({p.label, m}) : cells.at({"default", m});
    EXPECT_EQ(c.cells(), sum) << p.id;
    ++matched;
  }
  EXPECT_EQ(matched, configurations.size()) << "every synthesized configuration is a row of the width table";
  // A latency is a parameter too: the default widths with one more matrix-unit register were never synthesized.
  dp::ArpConfig c;
  c.timed.stage[static_cast<size_t>(dp::Stage::Rotate)].latency_cycles = 3;
  const sim::HardwareCost extra = sim::hardware_cost(c);
  EXPECT_FALSE(extra.fully_synthesized());
  EXPECT_EQ(extra.synthesized.size(), sim::rtl_module_keys().size() - 1);
}

TEST(Tradeoff, AWidthNotSynthesizedHasTheBitModelOnlyAndTheModelGrowsWithTheWidths) {
  std::map<std::string, sim::HardwareCost> cost;
  for (const auto& p : sim::trade_points(sim::TradeScale{false}))
    if (p.kind == TradeKind::Width) cost[p.label] = sim::hardware_cost(sim::trade_config(p));
  // Q1.16 changes the matrix unit and the address generator only: the composition
  // unit and the filter keep the default's synthesized parameters.
  const auto cells = csv_cells();
  EXPECT_FALSE(cost.at("q16").fully_synthesized());
  EXPECT_EQ(cost.at("q16").synthesized.size(), 2u);
  EXPECT_EQ(cost.at("q16").cells(), cells.at({"default", "comp"}) + cells.at({"default", "filt"}));
  const char* order[] = {"q11", "q12", "q13", "default", "q16"};
  for (size_t i = 1; i < std::size(order); ++i)
    EXPECT_LT(cost.at(order[i - 1]).model.multiplier_bits, cost.at(order[i]).model.multiplier_bits) << order[i];
  EXPECT_LT(cost.at("recip-index-6").model.table_bits, cost.at("default").model.table_bits);
  EXPECT_LT(cost.at("default").model.table_bits, cost.at("recip-index-10").model.table_bits);
  EXPECT_EQ(cost.at("exact").model.table_bits, 0) << "the exact divider has no reciprocal table";
}

TEST(Tradeoff, PointsAreUniqueFileNamesAndTheQuickSweepIsPartOfTheFullOne) {
  const auto full = sim::trade_points(sim::TradeScale{false});
  const auto quick = sim::trade_points(sim::TradeScale{true});
  std::set<std::string> ids;
  std::map<TradeKind, int> per_kind;
  for (const auto& p : full) {
    EXPECT_TRUE(ids.insert(p.id).second) << p.id;
    EXPECT_EQ(p.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789.-"), std::string::npos) << p.id;
    EXPECT_EQ(p.exclusive(), p.kind == TradeKind::Level || p.kind == TradeKind::Width) << p.id;
    ++per_kind[p.kind];
    EXPECT_NO_THROW(sim::trade_config(p)) << p.id;
  }
  EXPECT_EQ(per_kind.size(), 5u);
  for (const auto& [k, n] : per_kind) EXPECT_GE(n, 2) << sim::trade_kind_key(k);
  EXPECT_LT(quick.size(), full.size());
  for (const auto& p : quick) EXPECT_TRUE(ids.count(p.id)) << p.id;
  EXPECT_EQ(ids.count("level-verilated"), vl::verilated_available() ? 1u : 0u);
  const InputError e = test::error_of([&] { sim::find_trade_point(full, "level-nonsense"); });
  EXPECT_NE(std::string(e.what()).find("--point"), std::string::npos) << e.what();
}

TEST(Tradeoff, TheLocalRunnerKeepsSpeedPointsAloneAndCollectsEveryExitStatus) {
  test::TempDir dir;
  // Each command records when it ran; exclusive ones must overlap nothing.
  auto cmd = [&](const std::string& id, bool exclusive, int status) {
    const std::string f = dir.file(id);
    return sim::SweepCommand{id,
                             {"/bin/sh", "-c",
                              "date +%s%N > " + f + ".start; sleep 0.3; date +%s%N > " + f + ".end; exit " + std::to_string(status)},
                             dir.file(id + ".log"),
                             exclusive,
                             ""};
  };
  std::vector<sim::SweepCommand> cmds{cmd("s1", false, 0), cmd("x1", true, 0), cmd("s2", false, 3), cmd("x2", true, 0),
                                      cmd("s3", false, 0)};
  int updates = 0;
  const auto o = sim::run_sweep_locally(cmds, 2, [&](double, const std::string&) { ++updates; }, [] { return 0; });
  ASSERT_EQ(o.exit_status.size(), cmds.size());
  EXPECT_EQ(o.exit_status.at("s2"), 3);
  EXPECT_EQ(o.exit_status.at("x1"), 0);
  EXPECT_EQ(o.stop_signal, 0);
  EXPECT_GT(updates, static_cast<int>(cmds.size())) << "a line at each start and as points end";
  auto t = [&](const std::string& f) { return std::stoll(slurp(dir.file(f))); };
  bool shared_overlapped = false;
  for (const auto& a : cmds)
    for (const auto& b : cmds) {
      if (a.id >= b.id) continue;
      const bool overlap = t(a.id + ".start") < t(b.id + ".end") && t(b.id + ".start") < t(a.id + ".end");
      if (a.exclusive || b.exclusive) EXPECT_FALSE(overlap) << a.id << " ran beside " << b.id;
      else shared_overlapped |= overlap;
    }
  EXPECT_TRUE(shared_overlapped) << "two cores: the shared points run side by side";
}

TEST(Tradeoff, APointThatCannotStartFailsAloneWithTheReasonInItsLog) {
  test::TempDir dir;
  const std::vector<sim::SweepCommand> cmds{{"gone", {dir.file("no-such-arpsim")}, dir.file("gone.log"), true, ""},
                                            {"fine", {"/bin/sh", "-c", "exit 0"}, dir.file("fine.log"), false, ""}};
  const auto o = sim::run_sweep_locally(cmds, 2, {}, {});
  EXPECT_EQ(o.exit_status.at("gone"), 127);
  EXPECT_EQ(o.exit_status.at("fine"), 0);
  EXPECT_NE(slurp(dir.file("gone.log")).find("cannot start"), std::string::npos);
}

// A point inherits standard input (/dev/null), output and error (its log) and no other file of the sweep's process.
TEST(Tradeoff, APointInheritsNoOtherFileOfTheSweep) {
  test::TempDir dir;
  const int fd = ::open(dir.file("held").c_str(), O_WRONLY | O_CREAT, 0644);  // no O_CLOEXEC: would be inherited by default
  ASSERT_GE(fd, 3);
  const std::string probe = "test -e /proc/self/fd/" + std::to_string(fd) + " && echo inherited || echo closed";
  const auto o = sim::run_sweep_locally({{"probe", {"/bin/sh", "-c", probe}, dir.file("probe.log"), false, ""}}, 1, {}, {});
  ::close(fd);
  EXPECT_EQ(o.exit_status.at("probe"), 0);
  EXPECT_EQ(slurp(dir.file("probe.log")), "closed\n");
}

TEST(Tradeoff, AStoppedSweepEndsItsRunningPointsAndStartsNoMore) {
  test::TempDir dir;
  std::vector<sim::SweepCommand> cmds;
  for (int i = 0; i < 4; ++i)
    cmds.push_back({"p" + std::to_string(i), {"/bin/sh", "-c", "sleep 30"}, dir.file("p" + std::to_string(i) + ".log"), false, ""});
  // The second one ignores SIGTERM: it is killed once the grace period is over.
  cmds[1].argv = {"/bin/sh", "-c", "trap '' TERM; sleep 30"};
  const auto t0 = std::chrono::steady_clock::now();
  int polls = 0;
  const auto o = sim::run_sweep_locally(cmds, 2, {}, [&] { return ++polls > 3 ? SIGTERM : 0; }, 0.5);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
  EXPECT_EQ(o.stop_signal, SIGTERM);
  ASSERT_EQ(o.exit_status.size(), 2u) << "the two running points end, the other two never start";
  EXPECT_EQ(o.exit_status.at("p0"), -SIGTERM);
  EXPECT_EQ(o.exit_status.at("p1"), -SIGKILL);
}

TEST(Tradeoff, SlurmScriptsHaveTheSweepsShape) {
  test::TempDir dir;
  sim::SlurmSweep s;
  s.name = "sweep";
  s.shared_ids = {"a", "b", "c"};
  s.exclusive_ids = {"x"};
  s.point_command = "echo point $ID";
  s.merge_command = "echo merge";
  s.log_dir = dir.path();
  s.task_minutes = 1500;  // 1 day, 1 hour
  const auto files = sim::write_slurm_sweep(dir.file("slurm"), s);
  EXPECT_EQ(files.size(), 6u);
  const std::string shared = slurp(dir.file("slurm/points-shared.sbatch"));
  EXPECT_NE(shared.find("#SBATCH --array=0-2\n"), std::string::npos) << shared;
  EXPECT_EQ(shared.find("--exclusive"), std::string::npos);
  EXPECT_NE(shared.find("#SBATCH --time=1-01:00:00\n"), std::string::npos) << shared;
  EXPECT_NE(slurp(dir.file("slurm/merge.sbatch")).find("#SBATCH --time=0-00:10:00\n"), std::string::npos);
  const std::string excl = slurp(dir.file("slurm/points-exclusive.sbatch"));
  EXPECT_NE(excl.find("#SBATCH --array=0-0\n"), std::string::npos) << excl;
  EXPECT_NE(excl.find("#SBATCH --exclusive\n"), std::string::npos);
  EXPECT_EQ(slurp(dir.file("slurm/shared.ids")), "a\nb\nc\n");
  const std::string submit = slurp(dir.file("slurm/submit.sh"));
  EXPECT_NE(submit.find("sbatch --dependency=afterany${deps} merge.sbatch"), std::string::npos) << submit;
  for (const char* f : {"points-shared.sbatch", "points-exclusive.sbatch", "merge.sbatch", "submit.sh"})
    EXPECT_EQ(test::run_command("bash -n " + dir.file(std::string("slurm/") + f)).status, 0) << f;
  // An array task picks its point by SLURM_ARRAY_TASK_ID.
  const auto r = test::run_command("SLURM_ARRAY_TASK_ID=1 bash " + dir.file("slurm/points-shared.sbatch"));
  EXPECT_EQ(r.output, "point b\n");
  // Folders a script cannot name as they are, and another scheduler, are refused before anything is written.
  EXPECT_NE(std::string(test::error_of([&] { sim::check_slurm_sweep_paths("slurm", dir.file("a b"), dir.path()); }).what())
                .find("whitespace"),
            std::string::npos);
  EXPECT_NE(std::string(test::error_of([&] { sim::check_slurm_sweep_paths("slurm", dir.path(), "/x/$HOME"); }).what()).find("--out"),
            std::string::npos);
  EXPECT_NE(std::string(test::error_of([&] { sim::check_slurm_sweep_paths("pbs", dir.path(), dir.path()); }).what()).find("slurm"),
            std::string::npos);
  // The trade's array names the binary as well as the folder: each must stand in a script as it is.
  const sim::TradePlan plan = sim::make_trade_plan(sim::TradeScale{true});
  const sim::SlurmSweep ok = sim::trade_slurm_sweep(plan, "/data/trade", "/opt/arpsim");
  EXPECT_EQ(ok.merge_command, "\"${ARPSIM:-/opt/arpsim}\" tradeoff --out /data/trade --merge");
  EXPECT_EQ(ok.shared_ids.size() + ok.exclusive_ids.size(), plan.points.size());
  EXPECT_EQ(test::error_of([&] { sim::trade_slurm_sweep(plan, "/data/trade", "/opt/my arpsim"); }).source(), "the arpsim binary");
  EXPECT_EQ(test::error_of([&] { sim::trade_slurm_sweep(plan, "/data/$trade", "/opt/arpsim"); }).source(), "--out");
}

TEST(Tradeoff, MergeKeepsMissingAndBrokenPointsAsRowsWithTheReason) {
  test::TempDir dir;
  const sim::TradePlan plan = sim::make_trade_plan(sim::TradeScale{true});
  sim::write_trade_plan(dir.path(), plan);
  fs::create_directories(dir.file("points"));
  std::ofstream(dir.file("points/width-q12.json")) << "{ not json";
  std::ofstream(dir.file("points/theta-2.log")) << "starting\narpsim: error: the host ran out of luck\n";
  const sim::TradeTables t = sim::collect_trade_results(dir.path(), sim::read_trade_plan(dir.path()));
  EXPECT_TRUE(t.results.empty());
  EXPECT_EQ(t.missing.size(), plan.points.size());
  EXPECT_NE(t.missing.at("width-q12").find("width-q12.json"), std::string::npos) << t.missing.at("width-q12");
  EXPECT_NE(t.missing.at("theta-2").find("ran out of luck"), std::string::npos) << t.missing.at("theta-2");
  const std::string md = sim::trade_markdown(t, "2026-01-01");
  EXPECT_NE(md.find("| q12 | missing |"), std::string::npos);
  const std::string csv = sim::trade_csv(t, TradeKind::Theta);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3) << csv;
  // Two levels whose frames differ in one pixel hash: the table says so and gives the level no error figures.
  auto level = [&](const std::string& id, const std::string& second) {
    nlohmann::json r{{"id", id},
                     {"quick", true},
                     {"machine", "m"},
                     {"peak_rss_bytes", 1},
                     {"point_wall_s", 1},
                     {"figures",
                      {{"pixel_clocks_per_s", 1e6},
                       {"pixel_hashes", {"a", second}},
                       {"photon_hashes", {"p", "q"}}}}};
    std::ofstream(sim::trade_result_path(dir.path(), id)) << r.dump();
  };
  level("level-functional", "b");
  level("level-lt", "c");
  std::ofstream(sim::trade_result_path(dir.path(), "width-default"))
      << R"({"id": "width-default", "quick": true, "machine": "m", "peak_rss_bytes": 1, "point_wall_s": 1,
            "figures": {"texel_max": 0.5, "texel_mean": 0.25}})";
  const sim::TradeTables two = sim::collect_trade_results(dir.path(), plan);
  const std::string md2 = sim::trade_markdown(two, "2026-01-01");
  EXPECT_NE(md2.find("against functional: pixels differ in 1, photon times in 0 of 2 frames"), std::string::npos) << md2;
  EXPECT_NE(md2.find("| frames differ from functional |"), std::string::npos);
  EXPECT_NE(md2.find("| 0.5 / 0.25 |"), std::string::npos) << "the functional level's error is the default widths'";
  // A result of the wrong shape (a figure of the wrong type) or from another sweep is missing, not a crash.
  std::ofstream(sim::trade_result_path(dir.path(), "level-lt"))
      << R"({"id": "level-lt", "quick": true, "machine": "m", "peak_rss_bytes": "lots", "point_wall_s": 1, "figures": {}})";
  std::ofstream(sim::trade_result_path(dir.path(), "width-q10"))
      << R"({"id": "width-q10", "quick": true, "machine": "m", "peak_rss_bytes": 1, "point_wall_s": 1, "run": "old",
            "figures": {"texel_max": "big", "cost": 5}})";
  std::ofstream(sim::trade_result_path(dir.path(), "width-q12"))
      << R"({"id": "width-q12", "quick": true, "machine": "m", "peak_rss_bytes": 1, "point_wall_s": 1, "run": "now",
            "figures": {"texel_max": "big", "cost": 5}})";
  sim::TradePlan now = plan;
  now.run_id = "now";
  const sim::TradeTables odd = sim::collect_trade_results(dir.path(), now);
  EXPECT_NE(odd.missing.at("level-lt").find("peak_rss_bytes"), std::string::npos) << odd.missing.at("level-lt");
  EXPECT_NE(odd.missing.at("width-q10").find("another sweep (old)"), std::string::npos) << odd.missing.at("width-q10");
  ASSERT_TRUE(odd.results.count("width-q12"));
  const std::string odd_md = sim::trade_markdown(odd, "today");
  const auto q12_row = odd_md.find("| q12 |");
  ASSERT_NE(q12_row, std::string::npos);
  const std::string row = odd_md.substr(q12_row, odd_md.find('\n', q12_row) - q12_row);
  EXPECT_NE(row.find("| bad value in the result |"), std::string::npos) << row;
  EXPECT_NE(row.find("| — |"), std::string::npos) << row << ": a figure that is no number shows as none";
  // A plan from another build's point list is refused, naming the file.
  std::ofstream(dir.file("plan.json")) << R"({"quick": true, "points": ["level-golden"]})";
  const InputError e = test::error_of([&] { sim::read_trade_plan(dir.path()); });
  EXPECT_NE(std::string(e.what()).find("plan.json"), std::string::npos) << e.what();
}

// Two levels as standalone processes, merged: the cycle level's frames and
// photon times equal the functional level's (as tests/TimedRunCliTest
// requires of every level), so the table says so and gives it the
// functional level's error against the golden reference.
TEST(Tradeoff, LevelPointsRunAsProcessesAndTheMergeComparesTheirFrames) {
  test::TempDir dir;
  const std::string a = arp::test::kArpsim + " tradeoff -q --quick --out " + dir.path();
  ASSERT_EQ(test::run_command(a + " --plan-only").status, 0);
  for (const char* id : {"level-functional", "level-cycle"}) {
    const auto r = test::run_command(a + " --point " + id);
    ASSERT_EQ(r.status, 0) << id << ": " << r.output;
  }
  const auto bad = test::run_command(a + " --point level-nonsense");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--point"), std::string::npos) << bad.output;
  const auto merged = test::run_command(a + " --merge");
  EXPECT_EQ(merged.status, 1) << "points are missing: " << merged.output;
  const std::string levels = slurp(dir.file("levels.csv"));
  EXPECT_NE(levels.find("identical to functional: pixels and photon times; 6 frames"), std::string::npos) << levels;
  const std::string md = slurp(dir.file("tradeoff.md"));
  EXPECT_NE(md.find("| golden | missing |"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(dir.file("points/level-cycle.json")));
  EXPECT_GT(j["figures"]["pixel_clocks"].get<int64_t>(), 5 * 420000) << "six frames of 800 x 525 pixel clocks";
  EXPECT_GT(j["peak_rss_bytes"].get<int64_t>(), 0);
  const auto no_plan = test::run_command(arp::test::kArpsim + " tradeoff --merge --out " + dir.file("nowhere"));
  EXPECT_EQ(no_plan.status, 2);
  EXPECT_NE(no_plan.output.find("plan.json"), std::string::npos) << no_plan.output;
  const auto time_alone = test::run_command(a + " --plan-only --slurm-time 5");
  EXPECT_EQ(time_alone.status, 2);
  EXPECT_NE(time_alone.output.find("--slurm-time: only with --emit"), std::string::npos) << time_alone.output;
}

TEST(Tradeoff, TheCommittedPageHasTheTablesCurrentStructure) {
  const std::string doc = slurp(std::string(ARPSIM_SOURCE_DIR) + "/docs/tradeoff.md");
  const std::string block = sim::trade_doc_block(doc);
  ASSERT_FALSE(block.empty()) << "docs/tradeoff.md has no generated block";
  // The block is found after its begin marker, even with an end marker quoted earlier.
  EXPECT_EQ(sim::trade_doc_block("<!-- tradeoff:end -->\n<!-- tradeoff:begin -->\nX\n<!-- tradeoff:end -->\n"), "X\n");
  const bool quick = block.find("scale: quick") != std::string::npos;
  sim::TradeTables empty;
  empty.plan = sim::make_trade_plan(sim::TradeScale{quick});
  auto committed = sim::trade_markdown_structure(block);
  if (!vl::verilated_available())  // a build without Verilator (the sanitizer trees) lists no verilated level
    committed.erase(std::remove(committed.begin(), committed.end(), "row: verilated"), committed.end());
  EXPECT_EQ(committed, sim::trade_markdown_structure(sim::trade_markdown(empty, "today")))
      << "docs/tradeoff.md is stale: `arpsim tradeoff" << (quick ? " --quick" : "") << " --out DIR --doc docs/tradeoff.md`";
}

}  // namespace
}  // namespace arp
