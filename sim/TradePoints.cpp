#include "TradePoints.hpp"

#include <cstdio>

#include "common/InputError.hpp"
#include "rtl_model/verilated/VerilatedUnits.hpp"

namespace arp::sim {

const char* trade_kind_key(TradeKind k) {
  switch (k) {
    case TradeKind::Level: return "levels";
    case TradeKind::Width: return "widths";
    case TradeKind::Theta: return "theta";
    case TradeKind::Region: return "regions";
    case TradeKind::Latency: return "latency";
  }
  return "?";
}

namespace {

std::string number_id(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// The datapath widths of the trade. The first seven are the RTL's width
// configurations (rtl_model/hdl/configurations.txt), with the latencies and
// memory format those are synthesized with, so the cost column holds
// synthesis figures for them (tests/TradeoffTest checks every one matches);
// the others have the bit-count model only.
struct WidthRow {
  const char* name;
  std::vector<std::string> sets;
  bool quick;
};
const std::vector<WidthRow>& width_rows() {
  static const std::vector<WidthRow> rows{
      {"default", {}, true},
      {"q12", {"datapath.vec_frac=12", "datapath.mat_frac=12", "datapath.rot_frac=12"}, true},
      {"q10",
       {"datapath.vec_frac=10", "datapath.mat_frac=10", "datapath.rot_frac=10", "timed.rotate_latency=3",
        "timed.address_latency=6"},
       true},
      {"exact", {"datapath.divider=exact", "timed.address_latency=6"}, true},
      {"newton0", {"datapath.newton_steps=0"}, true},
      {"format565",
       {"datapath.texel_frac=6", "memory.count=8", "memory.red_bits=5", "memory.green_bits=6", "memory.blue_bits=5",
        "memory.depth_bits=24", "memory.background=[16,69,165]", "timed.compose_latency=2", "timed.filter_latency=3"},
       true},
      {"flag1", {"memory.count=2", "memory.depth_bits=1"}, true},
      {"q16", {"datapath.vec_frac=16", "datapath.mat_frac=16", "datapath.rot_frac=16"}, false},
      {"q13", {"datapath.vec_frac=13", "datapath.mat_frac=13", "datapath.rot_frac=13"}, false},
      {"q11", {"datapath.vec_frac=11", "datapath.mat_frac=11", "datapath.rot_frac=11"}, false},
      {"recip-index-6", {"datapath.recip_index_bits=6"}, false},
      {"recip-index-10", {"datapath.recip_index_bits=10"}, false},
      {"recip-frac-12", {"datapath.recip_frac_bits=12", "datapath.quot_frac=12"}, false},
      {"newton2", {"datapath.newton_steps=2"}, false},
      {"texel-frac-4", {"datapath.texel_frac=4"}, false},
  };
  return rows;
}

// The architect's knobs: one configuration change each against the defaults.
struct LatencyRow {
  const char* name;
  std::vector<std::string> sets;
  std::vector<std::string> stalls;
};
const std::vector<LatencyRow>& latency_rows() {
  static const std::vector<LatencyRow> rows{
      {"defaults (latch per scanline)", {}, {}},
      {"latch per frame", {"pipeline.latch=frame"}, {}},
      {"latch per field (interlaced)", {"pipeline.latch=field", "display.fields_per_frame=2"}, {}},
      {"latch per pixel", {"pipeline.latch=pixel"}, {}},
      {"one more matrix-unit register", {"timed.rotate_latency=3"}, {}},
      {"two more address registers", {"timed.address_latency=6"}, {}},
      {"FIFOs 8 deep", {"timed.fifo_depth=8"}, {}},
      {"FIFOs half (2, no issue slack)", {"timed.fifo_depth=2", "timed.issue_slack_cycles=0"}, {}},
      {"a 6-clock fetch stall", {}, {"fetch:100000:6"}},
      {"a 6-clock fetch stall, issue slack 8, FIFOs 10", {"timed.issue_slack_cycles=8", "timed.fifo_depth=10"}, {"fetch:100000:6"}},
      {"pixel clock x2 (120 Hz), one more fetch register", {"display.pixel_clock_hz=50350000", "timed.fetch_latency=3"}, {}},
      {"host clock 25 MHz", {"timed.host_clock_hz=25000000"}, {}},
      {"host clock 5 MHz", {"timed.host_clock_hz=5000000"}, {}},
      {"1 display memory", {"memory.count=1"}, {}},
      {"2 display memories", {"memory.count=2"}, {}},
      {"8 display memories", {"memory.count=8"}, {}},
  };
  return rows;
}

std::string slug(const std::string& s) {
  std::string out;
  for (char ch : s) {
    const bool word = (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9');
    if (ch >= 'A' && ch <= 'Z') out += static_cast<char>(ch - 'A' + 'a');
    else if (word) out += ch;
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

}  // namespace

std::vector<TradePoint> trade_points(const TradeScale& s) {
  std::vector<TradePoint> pts;
  std::vector<std::string> levels{"golden", "functional", "lt", "cycle", "detailed"};
  if (vl::verilated_available()) levels.push_back("verilated");
  for (const auto& l : levels) {
    TradePoint p;
    p.id = "level-" + l;
    p.kind = TradeKind::Level;
    p.label = l;
    p.level = l;
    pts.push_back(p);
  }
  for (const auto& w : width_rows()) {
    if (s.quick && !w.quick) continue;
    TradePoint p;
    p.id = std::string("width-") + w.name;
    p.kind = TradeKind::Width;
    p.label = w.name;
    p.sets = w.sets;
    pts.push_back(p);
  }
  const std::vector<double> thetas = s.quick ? std::vector<double>{0.5, 2, 8} : std::vector<double>{0.25, 0.5, 1, 2, 4, 8};
  for (double th : thetas) {
    TradePoint p;
    p.id = "theta-" + number_id(th);
    p.kind = TradeKind::Theta;
    p.label = number_id(th) + " deg";
    p.theta_deg = th;
    pts.push_back(p);
  }
  const std::vector<double> regions = s.quick ? std::vector<double>{0, 4} : std::vector<double>{0, 2, 4, 8};
  for (double r : regions) {
    TradePoint p;
    p.id = "region-" + number_id(r);
    p.kind = TradeKind::Region;
    p.label = r == 0 ? std::string("objects (no regions)") : number_id(r) + " m";
    p.region_m = r;
    pts.push_back(p);
  }
  for (const auto& l : latency_rows()) {
    TradePoint p;
    p.id = "latency-" + slug(l.name);
    p.kind = TradeKind::Latency;
    p.label = l.name;
    p.sets = l.sets;
    p.stalls = l.stalls;
    pts.push_back(p);
  }
  return pts;
}

const TradePoint& find_trade_point(const std::vector<TradePoint>& points, const std::string& id) {
  for (const auto& p : points)
    if (p.id == id) return p;
  std::string some;
  for (size_t i = 0; i < points.size() && i < 4; ++i) some += (i ? ", " : "") + points[i].id;
  throw InputError("--point", id, "no such point (" + std::to_string(points.size()) + " points, e.g. " + some +
                                      "; `arpsim tradeoff --list` lists them)");
}

}  // namespace arp::sim
