// The trade's tables from its points' result files (sim/TradeMeasure): one
// table per kind -- fidelity levels, datapath widths, theta_t, region size,
// the architect's latency knobs -- as CSV, JSON, markdown (the page
// docs/tradeoff.md is one of these) and gnuplot plots. Points without a
// result are rows marked missing, listed with the reason, never dropped.
#pragma once
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

#include "SweepRunner.hpp"
#include "TradePoints.hpp"

namespace arp::sim {

// The sweep as written to OUT/plan.json: its scale and points, so every
// point run and the merge (on any machine) agree on what the sweep is.
struct TradePlan {
  TradeScale scale;
  std::vector<TradePoint> points;
  // Names this sweep: every result carries it, and the merge takes no result
  // from another sweep (a point that failed this time keeps no old figures).
  std::string run_id;
};
TradePlan make_trade_plan(const TradeScale& s);
// A fresh run id: UTC time and process id ("20261124T183200Z-12345").
std::string new_trade_run_id();
// Removes the plan's result and log files under `dir` (an earlier sweep's).
void clear_trade_results(const std::string& dir, const TradePlan& p);
void write_trade_plan(const std::string& dir, const TradePlan& p);
// InputError naming the file when it is missing or not a plan this build understands.
TradePlan read_trade_plan(const std::string& dir);

// Where a point's result and log go.
std::string trade_result_path(const std::string& dir, const std::string& id);
std::string trade_log_path(const std::string& dir, const std::string& id);

// The plan's points as `binary tradeoff --point ID` processes, each logging
// beside its result (`dir` absolute: the processes may run elsewhere).
std::vector<SweepCommand> trade_sweep_commands(const TradePlan& plan, const std::string& dir, const std::string& binary);
// The same as a Slurm job array and its merge; $ARPSIM, when set where the
// jobs run, names the binary instead. InputError when `dir` or `binary`
// cannot stand in a script as it is (whitespace, quotes, $, `, \).
SlurmSweep trade_slurm_sweep(const TradePlan& plan, const std::string& dir, const std::string& binary);

struct TradeTables {
  TradePlan plan;
  std::map<std::string, nlohmann::json> results;  // by point id
  std::map<std::string, std::string> missing;     // id -> why
  std::string machine;  // the machines the results were measured on, "; "-separated
  double points_wall_s = 0;  // the points' own time, summed
  double sweep_wall_s = 0;   // the whole sweep's time when this process ran it (0: merged only)
  int sweep_jobs = 0;        // ... on this many cores
};

// Reads every result file of the plan under `dir` (a result that does not parse is missing, with the reason).
TradeTables collect_trade_results(const std::string& dir, const TradePlan& plan);

// The page: every table, the notes that explain it, what is missing. `date`: when it was merged.
std::string trade_markdown(const TradeTables& t, const std::string& date);
// CSV of one table (levels, widths, theta, regions, latency).
std::string trade_csv(const TradeTables& t, TradeKind k);

// Writes OUT/tradeoff.md, tradeoff.json, one CSV per table and the plots;
// returns notes for the user (plots not made, points missing).
std::vector<std::string> write_trade_outputs(const std::string& dir, const TradeTables& t, const std::string& date);

// `doc` with the text between its "<!-- tradeoff:begin -->" and "<!-- tradeoff:end -->" lines
// replaced by `markdown`; InputError naming `doc_name` when the markers are missing.
std::string update_trade_doc(const std::string& doc, const std::string& markdown, const std::string& doc_name);
// The generated part of a doc (between the markers), empty if none.
std::string trade_doc_block(const std::string& doc);

// The structure of a page (each table's header row and first-column labels), for the staleness test.
std::vector<std::string> trade_markdown_structure(const std::string& markdown);

}  // namespace arp::sim
