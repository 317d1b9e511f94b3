// The speed-accuracy trade as a list of points: each point is one
// measurement (a fidelity level's speed, a datapath width's error and cost,
// a theta_t or region size's load and image error, a latency knob's effect)
// that one standalone `arpsim tradeoff --point ID` computes into its own
// result file, so a sweep runs on the cores of one machine or as a cluster's
// job array alike, and a merge builds the tables (sim/TradeTable).
#pragma once
#include <string>
#include <vector>

namespace arp::sim {

// The tables of the trade, in the order they are printed.
enum class TradeKind { Level, Width, Theta, Region, Latency };
const char* trade_kind_key(TradeKind k);  // "levels", "widths", "theta", "regions", "latency"

struct TradePoint {
  std::string id;                 // unique; its result file is points/ID.json
  TradeKind kind = TradeKind::Level;
  std::string label;              // the row's name in its table
  std::string level;              // Level: golden, functional, lt, cycle, detailed, verilated
  std::vector<std::string> sets;  // configuration overrides (section.key=value) on the defaults
  double theta_deg = 0;           // Theta: theta_t (0: the host's default, one texel)
  double region_m = 0;            // Region: region size (0: object-level priority rendering)
  std::vector<std::string> stalls;  // Latency: injected stalls, STAGE:CLOCK:CYCLES as `arpsim run --stall`
  // The point measures speed: it runs alone on the machine (the others share the cores).
  bool exclusive() const { return kind == TradeKind::Level || kind == TradeKind::Width; }
};

// How much each point simulates: --quick (the whole trade in minutes) or the full run.
struct TradeScale {
  bool quick = false;
  int64_t level_frames() const { return quick ? 6 : 60; }
  int64_t width_frames() const { return quick ? 6 : 30; }
  int64_t host_frames() const { return quick ? 12 : 60; }    // theta and region points: the gallery walk
  int64_t host_error_every() const { return quick ? 4 : 5; }
  int64_t latency_frames() const { return quick ? 6 : 30; }
};

// The head speed the latency table states registration error at, deg/s.
constexpr double kTradeHeadSpeedDegS = 100.0;
// The levels' head motion: a steady turn about a generic axis (no face edge
// stays put), the same in every level so their frames can be compared.
constexpr double kLevelTurnDegS = 30.0;
constexpr double kLevelTurnAxis[3] = {0.3, 1.0, 0.2};

// Every point of the trade at this scale, in table order; the verilated level
// is listed only when this build has the verilated models.
std::vector<TradePoint> trade_points(const TradeScale& s);

// The point with this id; InputError naming --point and a few valid ids otherwise.
const TradePoint& find_trade_point(const std::vector<TradePoint>& points, const std::string& id);

}  // namespace arp::sim
