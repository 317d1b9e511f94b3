#include "TradeTable.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "HardwareCost.hpp"
#include "common/AtomicFile.hpp"
#include "common/Gnuplot.hpp"
#include "common/InputError.hpp"
#include "common/InputFile.hpp"
#include "common/StrictJson.hpp"

namespace arp::sim {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr TradeKind kKinds[] = {TradeKind::Level, TradeKind::Width, TradeKind::Theta, TradeKind::Region, TradeKind::Latency};
constexpr size_t kMaxResultBytes = size_t{1} << 26;

std::string fmt(double v, const char* f = "%.4g") {
  if (!std::isfinite(v)) return "—";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
double num(const json& f, const char* key) {
  return f.contains(key) && f[key].is_number() ? f[key].get<double>() : std::nan("");
}
double num_at(const json& f, const char* key, size_t i) {
  return f.contains(key) && f[key].is_array() && f[key].size() > i && f[key][i].is_number() ? f[key][i].get<double>()
                                                                                             : std::nan("");
}
std::string millions(double v) { return fmt(v / 1e6, "%.3g M"); }
std::string micros_of_ps(double ps) { return fmt(ps / 1e6, "%.3f"); }

// A table column: its markdown header and cell, its CSV name and value (raw numbers, or text).
struct Column {
  std::string header, csv;
  std::function<std::string(const TradeTables&, const TradePoint&, const json&)> md, raw;
};

const json& figures_of(const TradeTables& t, const std::string& id) {
  static const json none = json::object();
  const auto it = t.results.find(id);
  return it == t.results.end() ? none : it->second.at("figures");
}

// Levels: the datapath levels' error against the golden reference is the
// functional model's (the accuracy harness at the default widths, point
// width-default) wherever a level's frames equal the functional model's.
size_t differing(const json& a, const json& b, const char* key) {
  if (!a.contains(key) || !b.contains(key)) return SIZE_MAX;
  const auto& x = a[key];
  const auto& y = b[key];
  if (x.size() != y.size()) return SIZE_MAX;
  size_t n = 0;
  for (size_t i = 0; i < x.size(); ++i) n += x[i] != y[i];
  return n;
}
std::string previous_level(const TradeTables& t, const TradePoint& p) {
  std::string prev;
  for (const auto& q : t.plan.points) {
    if (q.id == p.id) return prev;
    if (q.kind == TradeKind::Level && t.results.count(q.id)) prev = q.id;
  }
  return prev;
}
bool same_frames_as_functional(const TradeTables& t, const TradePoint& p) {
  if (p.level == "functional") return true;
  const json& a = figures_of(t, p.id);
  const json& b = figures_of(t, "level-functional");
  return differing(a, b, "pixel_hashes") == 0 && differing(a, b, "photon_hashes") == 0;
}
std::string level_error(const TradeTables& t, const TradePoint& p, bool texel) {
  if (p.level == "golden") return "0 (the reference)";
  const json& w = figures_of(t, "width-default");
  if (w.empty()) return "— (width-default missing)";
  if (p.level != "functional" && !t.results.count("level-functional")) return "— (functional missing)";
  if (!same_frames_as_functional(t, p)) return "frames differ from functional";
  return texel ? fmt(num(w, "texel_max")) + " / " + fmt(num(w, "texel_mean"))
               : fmt(num(w, "color_max_lsb")) + " / " + fmt(num(w, "color_mean_lsb"));
}
std::string against_above(const TradeTables& t, const TradePoint& p) {
  if (p.level == "golden") return "—";
  if (p.level == "functional") return "bit-accurate datapath against exact arithmetic: the error columns";
  const std::string prev = previous_level(t, p);
  if (prev.empty()) return "— (no level above measured)";
  const json& a = figures_of(t, p.id);
  const json& b = figures_of(t, prev);
  const size_t px = differing(a, b, "pixel_hashes"), ph = differing(a, b, "photon_hashes");
  const std::string other = prev.substr(std::string("level-").size());
  if (px == SIZE_MAX || ph == SIZE_MAX) return "not comparable with " + other + " (frame counts differ)";
  const size_t n = a["pixel_hashes"].size();
  if (px == 0 && ph == 0) return "identical to " + other + ": pixels and photon times, " + std::to_string(n) + " frames";
  return "against " + other + ": pixels differ in " + std::to_string(px) + ", photon times in " + std::to_string(ph) + " of " +
         std::to_string(n) + " frames";
}

std::vector<Column> columns(TradeKind k) {
  using T = const TradeTables&;
  using P = const TradePoint&;
  using F = const json&;
  auto number = [](const char* key, const char* f) {
    return [key, f](T, P, F x) { return fmt(num(x, key), f); };
  };
  auto rawnum = [](const char* key) {
    return [key](T, P, F x) { return fmt(num(x, key), "%.9g"); };
  };
  auto label = [](T, P p, F) { return p.label; };
  auto speed = [](T, P, F x) { return millions(num(x, "pixel_clocks_per_s")); };
  auto realtime = [](T, P, F x) { return fmt(num(x, "real_time_fraction"), "%.3g"); };
  auto rss = [](T t, P p, F) {
    const auto it = t.results.find(p.id);
    return it == t.results.end() ? std::string("—") : fmt(it->second.at("peak_rss_bytes").get<double>() / 1048576.0, "%.0f");
  };
  auto rss_raw = [](T t, P p, F) {
    const auto it = t.results.find(p.id);
    return it == t.results.end() ? std::string() : fmt(it->second.at("peak_rss_bytes").get<double>(), "%.0f");
  };
  switch (k) {
    case TradeKind::Level:
      return {{"level", "level", label, label},
              {"what it models", "models", [](T, P, F x) { return x.value("describes", std::string("—")); },
               [](T, P, F x) { return x.value("describes", std::string()); }},
              {"pixel clocks/s", "pixel_clocks_per_s", speed, rawnum("pixel_clocks_per_s")},
              {"× real time", "real_time_fraction", realtime, rawnum("real_time_fraction")},
              {"peak RSS (MiB)", "peak_rss_bytes", rss, rss_raw},
              {"texel error max / mean (texels)", "texel_error_vs_golden",
               [=](T t, P p, F) { return level_error(t, p, true); }, [=](T t, P p, F) { return level_error(t, p, true); }},
              {"colour error max / mean (LSB)", "colour_error_vs_golden",
               [=](T t, P p, F) { return level_error(t, p, false); }, [=](T t, P p, F) { return level_error(t, p, false); }},
              {"against the level above", "against_above", [](T t, P p, F) { return against_above(t, p); },
               [](T t, P p, F) { return against_above(t, p); }}};
    case TradeKind::Width:
      return {{"widths", "width", label, label},
              {"overrides", "overrides",
               [](T, P p, F) {
                 std::string s;
                 for (const auto& o : p.sets) s += (s.empty() ? "" : " ") + ("`" + o + "`");
                 return s.empty() ? std::string("(defaults)") : s;
               },
               [](T, P p, F) {
                 std::string s;
                 for (const auto& o : p.sets) s += (s.empty() ? "" : " ") + o;
                 return s;
               }},
              {"texel max", "texel_max", number("texel_max", "%.4g"), rawnum("texel_max")},
              {"texel mean", "texel_mean", number("texel_mean", "%.4g"), rawnum("texel_mean")},
              {"exact texel (pooled)", "texel_exact_share", [](T, P, F x) { return fmt(100 * num(x, "texel_exact_share"), "%.2f %%"); },
               rawnum("texel_exact_share")},
              {"worst generic view: exact / max", "worst_view_exact_share",
               [](T, P, F x) {
                 return fmt(100 * num(x, "worst_view_exact_share"), "%.2f %%") + " / " + fmt(num(x, "worst_view_max"), "%.4g");
               },
               rawnum("worst_view_exact_share")},
              {"aligned views: exact among non-ties / max", "aligned_exact_share_nontie",
               [](T, P, F x) {
                 return fmt(100 * num(x, "aligned_exact_share_nontie"), "%.2f %%") + " / " + fmt(num(x, "aligned_max"), "%.4g");
               },
               rawnum("aligned_exact_share_nontie")},
              {"colour max / 99.9 % / mean (LSB)", "color_lsb",
               [](T, P, F x) {
                 return fmt(num(x, "color_max_lsb"), "%.3g") + " / " + fmt(num(x, "color_p999_lsb"), "%.3g") + " / " +
                        fmt(num(x, "color_mean_lsb"), "%.3g");
               },
               rawnum("color_max_lsb")},
              {"functional pixel clocks/s", "pixel_clocks_per_s", speed, rawnum("pixel_clocks_per_s")},
              {"cells (synthesized)", "cells",
               [](T, P, F x) {
                 if (!x.contains("cost")) return std::string("—");
                 const json& c = x["cost"];
                 return c.value("fully_synthesized", false) ? fmt(c.value("cells", 0.0), "%.0f") : std::string("not synthesized");
               },
               [](T, P, F x) {
                 return x.contains("cost") && x["cost"].value("fully_synthesized", false) ? fmt(x["cost"].value("cells", 0.0), "%.0f")
                                                                                           : std::string();
               }},
              {"iCE40 LUT4 / depth", "ice40_lut4",
               [](T, P, F x) {
                 if (!x.contains("cost") || !x["cost"].value("fully_synthesized", false)) return std::string("—");
                 return fmt(x["cost"].value("ice40_lut4", 0.0), "%.0f") + " / " + fmt(x["cost"].value("logic_depth", 0.0), "%.0f");
               },
               [](T, P, F x) {
                 return x.contains("cost") && x["cost"].value("fully_synthesized", false)
                            ? fmt(x["cost"].value("ice40_lut4", 0.0), "%.0f")
                            : std::string();
               }},
              {"bit model: multiplier / adder / table bits", "model_bits",
               [](T, P, F x) {
                 if (!x.contains("cost")) return std::string("—");
                 const json& c = x["cost"];
                 return fmt(c.value("model_multiplier_bits", 0.0), "%.0f") + " / " + fmt(c.value("model_adder_bits", 0.0), "%.0f") +
                        " / " + fmt(c.value("model_table_bits", 0.0), "%.0f");
               },
               [](T, P, F x) { return x.contains("cost") ? fmt(x["cost"].value("model_multiplier_bits", 0.0), "%.0f") : std::string(); }}};
    case TradeKind::Theta:
    case TradeKind::Region: {
      std::vector<Column> c{{k == TradeKind::Theta ? "θt" : "region size", k == TradeKind::Theta ? "theta" : "region", label, label},
                            {"triangles/s rendered", "triangles_per_s", [](T, P, F x) { return millions(num(x, "triangles_per_s")); },
                             rawnum("triangles_per_s")},
                            {"load reduction (× fewer than every object every frame)", "load_reduction",
                             number("load_reduction", "%.2f"), rawnum("load_reduction")},
                            {"PSNR mean / worst (dB)", "mean_psnr_db",
                             [](T, P, F x) { return fmt(num(x, "mean_psnr_db"), "%.1f") + " / " + fmt(num(x, "worst_psnr_db"), "%.1f"); },
                             rawnum("mean_psnr_db")},
                            {"worst displacement (px)", "max_displacement_px", number("max_displacement_px", "%.2f"),
                             rawnum("max_displacement_px")},
                            {"worst share showing another object", "worst_share_another_object",
                             [](T, P, F x) { return fmt(100 * num(x, "worst_share_another_object"), "%.2f %%"); },
                             rawnum("worst_share_another_object")},
                            {"host ms per frame (wall)", "host_wall_ms_per_frame", number("host_wall_ms_per_frame", "%.1f"),
                             rawnum("host_wall_ms_per_frame")}};
      if (k == TradeKind::Region)
        c.push_back({"mean tear (px)", "mean_tear_pixels", number("mean_tear_pixels", "%.1f"), rawnum("mean_tear_pixels")});
      return c;
    }
    case TradeKind::Latency:
      return {{"change against the defaults", "change", label, label},
              {"orientation-to-photon latency min / median / max (µs)", "latency_median_ps",
               [](T, P, F x) {
                 return micros_of_ps(num_at(x, "latency_ps", 0)) + " / " + micros_of_ps(num_at(x, "latency_ps", 1)) + " / " +
                        micros_of_ps(num_at(x, "latency_ps", 2));
               },
               [](T, P, F x) { return fmt(num_at(x, "latency_ps", 1), "%.0f"); }},
              {"latch → photon lead (ns)", "orientation_lead_ns", number("orientation_lead_ns", "%.0f"), rawnum("orientation_lead_ns")},
              {"registration at " + fmt(kTradeHeadSpeedDegS, "%g") + " °/s median / max (px)", "registration_max_px",
               [](T, P, F x) {
                 return fmt(num_at(x, "registration_px", 1), "%.2f") + " / " + fmt(num_at(x, "registration_px", 2), "%.2f");
               },
               [](T, P, F x) { return fmt(num_at(x, "registration_px", 2), "%.6g"); }},
              {"underflows", "underflows", number("underflows", "%.0f"), rawnum("underflows")},
              {"refresh (Hz)", "refresh_hz", number("refresh_hz", "%.2f"), rawnum("refresh_hz")},
              {"cells (synthesized)", "cells",
               [](T, P, F x) { return x.contains("cells") && x["cells"].is_number() ? fmt(x["cells"].get<double>(), "%.0f") : "not synthesized"; },
               [](T, P, F x) { return x.contains("cells") && x["cells"].is_number() ? fmt(x["cells"].get<double>(), "%.0f") : ""; }},
              {"late pixels dropped", "late_discarded", number("late_discarded", "%.0f"), rawnum("late_discarded")},
              {"speed with the host (pixel clocks/s)", "pixel_clocks_per_s", speed, rawnum("pixel_clocks_per_s")}};
  }
  return {};
}

// A cell; a figure of the wrong type in a result file shows as such, not as a crash.
std::string cell(const std::function<std::string(const TradeTables&, const TradePoint&, const json&)>& f, const TradeTables& t,
                 const TradePoint& p) {
  try {
    return f(t, p, figures_of(t, p.id));
  } catch (const json::exception&) {
    return "bad value in the result";
  }
}

const char* table_title(TradeKind k) {
  switch (k) {
    case TradeKind::Level: return "Fidelity levels: speed against error";
    case TradeKind::Width: return "Datapath widths: error, speed and hardware cost";
    case TradeKind::Theta: return "Priority rendering: load against image error (θt)";
    case TradeKind::Region: return "Region priority rendering: region size";
    case TradeKind::Latency: return "The architect's latency sweep (fast cycle level)";
  }
  return "?";
}

std::string table_note(TradeKind k, const TradeScale& s) {
  switch (k) {
    case TradeKind::Level:
      return "Each level renders the calibration memories under a " + fmt(kLevelTurnDegS, "%g") + " °/s turn, " +
             std::to_string(s.level_frames()) +
             " frames (pixel clocks counted from the first to the last frame's scan-out; the golden reference renders whole "
             "frames of the same turn, one orientation per frame, untimed).";
    case TradeKind::Width:
      return "Error: the accuracy harness (`arpsim verify`) at these widths against the golden reference. Speed: the functional "
             "level at these widths. Cells: yosys `synth` of the four RTL modules summed, where the RTL was synthesized with "
             "exactly these parameters; the bit model (multiplier a×b bits, adder bits, table bits) is a model for ranking "
             "widths, not a cell count.";
    case TradeKind::Theta:
      return "The gallery walk with priority rendering (objects), error against the truth rendered fresh for every measured frame.";
    case TradeKind::Region:
      return "The gallery walk with region priority rendering (margin = size / 8, θt one texel); objects: no regions.";
    case TradeKind::Latency:
      return "The gallery walk under a steady " + fmt(kTradeHeadSpeedDegS, "%g") +
             " °/s turn at the fast cycle level; one change against the defaults per row "
             "(stalls injected as `arpsim run --stall fetch:100000:6`). Latency: from the tracker sample the orientation "
             "register held to the pixel's photon, over every pixel; lead: from the register's latch to the photon of the "
             "pixel it was latched for (the pipeline's own part). Registration: " + fmt(kTradeHeadSpeedDegS, "%g") +
             " °/s × latency, in display pixels at "
             "the view's centre (a steady turn, no prediction). Cells: the four RTL modules, where synthesized with these "
             "parameters; FIFO storage is not in the RTL.";
  }
  return "";
}

std::string md_escape(std::string s) {
  for (size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}

}  // namespace

TradePlan make_trade_plan(const TradeScale& s) { return {s, trade_points(s), ""}; }

std::string new_trade_run_id() {
  const std::time_t now = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  return std::string(b) + "-" + std::to_string(::getpid());
}

void clear_trade_results(const std::string& dir, const TradePlan& p) {
  std::error_code ec;
  for (const auto& q : p.points) {
    fs::remove(trade_result_path(dir, q.id), ec);
    fs::remove(trade_log_path(dir, q.id), ec);
  }
}

void write_trade_plan(const std::string& dir, const TradePlan& p) {
  json ids = json::array();
  for (const auto& q : p.points) ids.push_back(q.id);
  write_text_atomic((fs::path(dir) / "plan.json").string(),
                    json{{"tool", "arpsim tradeoff"}, {"quick", p.scale.quick}, {"run", p.run_id}, {"points", ids}}.dump(2) + "\n");
}

TradePlan read_trade_plan(const std::string& dir) {
  const std::string path = (fs::path(dir) / "plan.json").string();
  if (!fs::exists(path))
    throw InputError(path, "", "no plan here: `arpsim tradeoff --out " + dir + " --plan-only` (or a whole run) writes it");
  const json j = parse_strict_json(read_input_file(path, 1 << 20, "tradeoff plan"), path);
  if (!j.is_object() || !j.contains("quick") || !j["quick"].is_boolean() || !j.contains("points") || !j["points"].is_array())
    throw InputError(path, "", "not a tradeoff plan (needs \"quick\" and \"points\")");
  TradePlan p = make_trade_plan(TradeScale{j["quick"].get<bool>()});
  if (j.contains("run") && j["run"].is_string()) p.run_id = j["run"].get<std::string>();
  std::vector<std::string> want, have;
  for (const auto& id : j["points"]) want.push_back(id.is_string() ? id.get<std::string>() : id.dump());
  for (const auto& q : p.points) have.push_back(q.id);
  if (want != have) {
    size_t i = 0;
    while (i < want.size() && i < have.size() && want[i] == have[i]) ++i;
    const std::string first = i < want.size() ? "'" + want[i] + "'" : "no point";
    const std::string ours = i < have.size() ? "'" + have[i] + "'" : "no point";
    throw InputError(path, "points", "written by a build with another point list (point " + std::to_string(i + 1) + " is " + first +
                                         ", this build has " + ours + "); write the plan again with this build");
  }
  return p;
}

std::string trade_result_path(const std::string& dir, const std::string& id) {
  return (fs::path(dir) / "points" / (id + ".json")).string();
}
std::string trade_log_path(const std::string& dir, const std::string& id) {
  return (fs::path(dir) / "points" / (id + ".log")).string();
}

std::vector<SweepCommand> trade_sweep_commands(const TradePlan& plan, const std::string& dir, const std::string& binary) {
  std::vector<SweepCommand> cmds;
  for (const auto& p : plan.points)
    cmds.push_back({p.id, {binary, "tradeoff", "-q", "--out", dir, "--point", p.id}, trade_log_path(dir, p.id), p.exclusive(),
                    "/proc/self/exe"});  // this very binary, even if a build replaces the file meanwhile
  return cmds;
}

SlurmSweep trade_slurm_sweep(const TradePlan& plan, const std::string& dir, const std::string& binary) {
  SlurmSweep s;
  s.name = "arpsim-tradeoff";
  for (const auto& p : plan.points) (p.exclusive() ? s.exclusive_ids : s.shared_ids).push_back(p.id);
  check_slurm_word("the arpsim binary", binary);
  check_slurm_word("--out", dir);
  const std::string bin = "\"${ARPSIM:-" + binary + "}\"";
  s.point_command = bin + " tradeoff -q --out " + dir + " --point \"$ID\" > " + dir + "/points/\"$ID\".log 2>&1";
  s.merge_command = bin + " tradeoff --out " + dir + " --merge";
  s.log_dir = (fs::path(dir) / "points").string();
  return s;
}

TradeTables collect_trade_results(const std::string& dir, const TradePlan& plan) {
  TradeTables t;
  t.plan = plan;
  for (const auto& p : plan.points) {
    const std::string path = trade_result_path(dir, p.id);
    if (!fs::exists(path)) {
      std::string why = "no result";
      std::ifstream log(trade_log_path(dir, p.id));
      std::string line, last;
      while (std::getline(log, line))
        if (!line.empty() && line.find('\r') == std::string::npos) last = line;
      if (!last.empty()) why += " (its log ends: " + last + ")";
      t.missing[p.id] = why;
      continue;
    }
    try {
      json r = parse_strict_json(read_input_file(path, kMaxResultBytes, "tradeoff result"), path);
      auto has = [&](const char* key, json::value_t type) { return r.contains(key) && r[key].type() == type; };
      if (!r.is_object() || !has("id", json::value_t::string) || r["id"] != p.id || !has("figures", json::value_t::object) ||
          !has("quick", json::value_t::boolean) || !has("machine", json::value_t::string) || !r.contains("peak_rss_bytes") ||
          !r["peak_rss_bytes"].is_number() || !r.contains("point_wall_s") || !r["point_wall_s"].is_number())
        throw InputError(path, "", "not the result of point " + p.id + " (id, quick, machine, peak_rss_bytes, point_wall_s, figures)");
      if (r["quick"].get<bool>() != plan.scale.quick) throw InputError(path, "quick", "measured at another scale than the plan");
      if (!plan.run_id.empty() && r.value("run", std::string()) != plan.run_id)
        throw InputError(path, "run", "left by another sweep (" + r.value("run", std::string("no run id")) + "), not this one (" +
                                          plan.run_id + ")");
      const std::string machine = r["machine"].get<std::string>();
      if (t.machine.find(machine) == std::string::npos) t.machine += (t.machine.empty() ? "" : "; ") + machine;
      t.points_wall_s += r["point_wall_s"].get<double>();
      t.results[p.id] = std::move(r);
    } catch (const InputError& e) {
      t.missing[p.id] = e.what();
    } catch (const json::exception& e) {
      t.missing[p.id] = path + ": " + e.what();
    }
  }
  return t;
}

std::string trade_markdown(const TradeTables& t, const std::string& date) {
  std::ostringstream md;
  md << "Measured by `arpsim tradeoff" << (t.plan.scale.quick ? " --quick" : "") << "` on " << date << ", "
     << (t.machine.empty() ? std::string("no machine recorded") : t.machine) << "; scale: " << (t.plan.scale.quick ? "quick" : "full")
     << "; " << t.results.size() << " of " << t.plan.points.size() << " points, " << fmt(t.points_wall_s, "%.0f")
     << " s of point time";
  if (t.sweep_wall_s > 0) md << "; the sweep took " << fmt(t.sweep_wall_s, "%.0f") << " s on " << t.sweep_jobs << " cores";
  md << ".\n";
  for (TradeKind k : kKinds) {
    const auto cols = columns(k);
    md << "\n### " << table_title(k) << "\n\n" << table_note(k, t.plan.scale) << "\n\n|";
    for (const auto& c : cols) md << " " << c.header << " |";
    md << "\n|";
    for (size_t i = 0; i < cols.size(); ++i) md << " --- |";
    md << "\n";
    for (const auto& p : t.plan.points) {
      if (p.kind != k) continue;
      const bool have = t.results.count(p.id) != 0;
      md << "|";
      for (size_t i = 0; i < cols.size(); ++i)
        md << " " << md_escape(i == 0 || have ? cell(cols[i].md, t, p) : std::string("missing")) << " |";
      md << "\n";
    }
  }
  if (!t.missing.empty()) {
    md << "\nMissing points (rerun one with `arpsim tradeoff --out DIR --point ID`, then `--merge`):\n\n";
    for (const auto& [id, why] : t.missing) md << "- `" << id << "`: " << why << "\n";
  }
  md << "\nHardware cost source: " << hardware_cost_source() << ".\n";
  return md.str();
}

std::string trade_csv(const TradeTables& t, TradeKind k) {
  const auto cols = columns(k);
  std::string out = "point";
  for (const auto& c : cols) out += "," + c.csv;
  out += "\n";
  for (const auto& p : t.plan.points) {
    if (p.kind != k) continue;
    out += p.id;
    const bool have = t.results.count(p.id) != 0;
    for (size_t i = 0; i < cols.size(); ++i) {
      std::string v = have || i == 0 ? cell(cols[i].raw, t, p) : std::string();
      if (v == "—") v.clear();
      for (char& ch : v)
        if (ch == ',') ch = ';';  // text cells: no separator inside (gnuplot and spreadsheets read the file as is)
      out += "," + v;
    }
    out += "\n";
  }
  return out;
}

namespace {
constexpr const char* kBegin = "<!-- tradeoff:begin -->\n";
constexpr const char* kEnd = "<!-- tradeoff:end -->";
}  // namespace

std::string trade_doc_block(const std::string& doc) {
  const auto b = doc.find(kBegin), e = b == std::string::npos ? b : doc.find(kEnd, b);
  if (b == std::string::npos || e == std::string::npos || e < b) return "";
  return doc.substr(b + std::strlen(kBegin), e - b - std::strlen(kBegin));
}

std::string update_trade_doc(const std::string& doc, const std::string& markdown, const std::string& doc_name) {
  const auto b = doc.find(kBegin), e = b == std::string::npos ? b : doc.find(kEnd, b);
  if (b == std::string::npos || e == std::string::npos || e < b)
    throw InputError(doc_name, "", std::string("no generated block: the doc needs the lines ") + "<!-- tradeoff:begin --> and " + kEnd);
  return doc.substr(0, b + std::strlen(kBegin)) + markdown + doc.substr(e);
}

std::vector<std::string> trade_markdown_structure(const std::string& markdown) {
  std::vector<std::string> s;
  std::istringstream in(markdown);
  std::string line;
  bool header_next = false;
  while (std::getline(in, line)) {
    if (line.rfind("### ", 0) == 0) {
      s.push_back(line);
      header_next = true;
    } else if (line.rfind("| ", 0) == 0) {
      if (header_next) {
        s.push_back(line);  // the header row, whole
        header_next = false;
      } else {
        s.push_back("row: " + line.substr(2, line.find(" |", 2) - 2));  // the first column: the row's name
      }
    }
  }
  return s;
}

namespace {
// Column `csv` of a kind's CSV, numbered as gnuplot counts (1: the point id), from the one column list.
std::string csv_column(TradeKind k, const std::string& csv) {
  const auto cols = columns(k);
  for (size_t i = 0; i < cols.size(); ++i)
    if (cols[i].csv == csv) return std::to_string(i + 2);
  throw std::logic_error(std::string("trade table ") + trade_kind_key(k) + " has no column " + csv);
}
}  // namespace

std::vector<std::string> write_trade_outputs(const std::string& dir, const TradeTables& t, const std::string& date) {
  std::vector<std::string> notes;
  const fs::path d(dir);
  for (TradeKind k : kKinds) write_text_atomic((d / (std::string(trade_kind_key(k)) + ".csv")).string(), trade_csv(t, k));
  json all{{"date", date}, {"machine", t.machine}, {"quick", t.plan.scale.quick}, {"points", json::object()}, {"missing", t.missing}};
  for (const auto& [id, r] : t.results) all["points"][id] = r;
  write_text_atomic((d / "tradeoff.json").string(), all.dump(1) + "\n");
  write_text_atomic((d / "tradeoff.md").string(), "# The speed–accuracy trade\n\n" + trade_markdown(t, date));
  const std::string common = "set terminal pngcairo size 960,600 font ',11'\nset datafile separator ','\nset key outside right\n"
                             "set grid\n";
  using K = TradeKind;
  auto col = csv_column;
  auto file = [](TradeKind k) { return std::string("'") + trade_kind_key(k) + ".csv'"; };
  const std::string w_err = col(K::Width, "texel_max"), w_speed = col(K::Width, "pixel_clocks_per_s"), w_name = col(K::Width, "width");
  const std::string t_load = col(K::Theta, "triangles_per_s"), t_psnr = col(K::Theta, "mean_psnr_db"), t_name = col(K::Theta, "theta");
  const std::string r_load = col(K::Region, "triangles_per_s"), r_psnr = col(K::Region, "mean_psnr_db"), r_name = col(K::Region, "region");
  const std::string speed =
      common +
      "set output 'speed-vs-error.png'\nset title 'Speed against texel error: one point per datapath width (functional level)'\n"
      "set logscale xy\nset xlabel 'worst texel-position error against the golden reference (texels)'\n"
      "set ylabel 'simulated pixel clocks per second'\n"
      "plot " + file(K::Width) + " every ::1 using " + w_err + ":" + w_speed + " with points pt 7 ps 1.5 title 'widths', "
      "'' every ::1 using " + w_err + ":" + w_speed + ":" + w_name + " with labels offset 1,0.6 left notitle\n";
  const std::string load =
      common +
      "set output 'load-vs-error.png'\nset title 'Rendering load against image error on the gallery walk'\n"
      "set xlabel 'triangles rendered per second'\nset ylabel 'mean PSNR against the truth (dB)'\nset logscale x\n"
      "plot " + file(K::Theta) + " every ::1 using " + t_load + ":" + t_psnr + " with linespoints pt 7 lw 2 title 'theta_t', "
      "'' every ::1 using " + t_load + ":" + t_psnr + ":" + t_name + " with labels offset 0.8,0.8 left notitle, " +
      file(K::Region) + " every ::1 using " + r_load + ":" + r_psnr + " with points pt 5 ps 1.5 title 'region size', "
      "'' every ::1 using " + r_load + ":" + r_psnr + ":" + r_name + " with labels offset 0.8,-0.8 left notitle\n";
  const std::string levels =
      common +
      "set output 'levels-speed.png'\nset title 'Simulation speed of each fidelity level'\nset style data histogram\n"
      "set style fill solid 0.6\nset logscale y\nset ylabel 'simulated pixel clocks per second'\nset xtics rotate by -30\n"
      "plot " + file(K::Level) + " every ::1 using " + col(K::Level, "pixel_clocks_per_s") + ":xtic(" + col(K::Level, "level") +
      ") title 'pixel clocks/s'\n";
  // The latency plot's data: min, median and max per change, in microseconds.
  std::string lat = "change,min_us,median_us,max_us\n";
  for (const auto& p : t.plan.points) {
    if (p.kind != TradeKind::Latency || !t.results.count(p.id)) continue;
    const json& f = figures_of(t, p.id);
    std::string name = p.label;
    for (char& ch : name)
      if (ch == ',') ch = ';';
    lat += name + "," + fmt(num_at(f, "latency_ps", 0) / 1e6, "%.6g") + "," + fmt(num_at(f, "latency_ps", 1) / 1e6, "%.6g") + "," +
           fmt(num_at(f, "latency_ps", 2) / 1e6, "%.6g") + "\n";
  }
  write_text_atomic((d / "latency-plot.csv").string(), lat);
  const std::string latency =
      common +
      "set output 'latency.png'\nset title 'Orientation-to-photon latency per change: median, bars from min to max'\n"
      "set logscale y\nset ylabel 'latency (microseconds)'\nset xtics rotate by -40 font ',9'\nset bmargin 14\n"
      "set boxwidth 0.6\nset style fill solid 0.5\n"
      "plot 'latency-plot.csv' every ::1 using 0:3:xtic(1) with boxes title 'median', "
      "'' every ::1 using 0:3:2:4 with yerrorbars pt 7 lw 2 title 'min .. max'\n";
  for (const auto& [name, text] : {std::pair<const char*, const std::string*>{"speed-vs-error.gp", &speed},
                                   {"load-vs-error.gp", &load}, {"levels-speed.gp", &levels}, {"latency.gp", &latency}}) {
    const std::string note = run_gnuplot(d / name, *text);
    if (!note.empty()) notes.push_back(note);
  }
  for (const auto& [id, why] : t.missing) notes.push_back("missing point " + id + ": " + why);
  return notes;
}

}  // namespace arp::sim
