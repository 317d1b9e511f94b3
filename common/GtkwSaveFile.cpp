#include "GtkwSaveFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <charconv>
#include <map>
#include <sstream>
#include <vector>

#include "common/InputError.hpp"
#include "common/InputFile.hpp"

namespace arp {

namespace {
constexpr double kWavePixels = 1000;  // [size] 1600 wide, less the tree and signal panes
constexpr size_t kMaxScopeDepth = 256, kMaxVars = 1'000'000;  // far beyond any model's

struct Var {
  std::string path;  // scope.name[range]
  std::string group;
  std::string leaf;
  int width;
};

// Binary for single bits, signed decimal for vectors and matrix entries,
// decimal for counts and positions, hex for colours and memory words.
const char* flags_for(const Var& v) {
  if (v.width == 1) return "@28";
  static const char* const signed_decimal[] = {"view_", "world_", "matrix_", "_q14"};
  for (const char* d : signed_decimal)
    if (v.leaf.find(d) != std::string::npos) return "@424";
  static const char* const decimal[] = {"count", "cycle", "frame", "sample", "occupancy", "backlog", "underflows",
                                        "job", "written", "line", "face", "texel_", "weight_"};
  if (v.leaf == "x" || v.leaf == "y") return "@24";
  for (const char* d : decimal)
    if (v.leaf.find(d) != std::string::npos) return "@24";
  return "@22";
}

// Clocks and scan position first, then the data path in pipeline order.
int group_rank(const std::string& g) {
  static const char* const order[] = {"clocks", "dut", "video_timing_generator", "tracker_interface", "lens_vector_table",
                                      "orientation_matrix_unit", "cube_face_address_generator", "display_memory_banks",
                                      "composition_unit", "anti_aliasing_filter", "hmd_scan_out", "fifos"};
  for (int i = 0; i < static_cast<int>(sizeof order / sizeof *order); ++i)
    if (g == order[i]) return i;
  return 100;
}
}  // namespace

std::string gtkw_for_vcd(const std::string& vcd_path, const std::string& dumpfile, int64_t view) {
  const auto in = open_input_stream(vcd_path, "waveform");
  return gtkw_for_vcd(*in, vcd_path, dumpfile, view);
}

std::string gtkw_for_vcd(std::istream& in, const std::string& vcd_path, const std::string& dumpfile, int64_t view) {
  LineReader lines(in, vcd_path);
  std::vector<std::string> scope;
  std::vector<Var> vars;
  std::string line;
  bool ended = false, in_comment = false;
  while (lines.next(line)) {
    std::istringstream ss(line);
    std::string tok;
    ss >> tok;
    if (tok == "$comment" || in_comment) {  // its words are no commands, up to its $end (maybe lines later)
      std::string t = in_comment ? tok : std::string();
      in_comment = true;
      do {
        if (t == "$end") in_comment = false;
      } while (in_comment && ss >> t);
      continue;
    }
    if (tok == "$scope") {
      std::string kind, name;
      ss >> kind >> name;
      if (scope.size() == kMaxScopeDepth)
        throw InputError(vcd_path, lines.where(), "scopes nested deeper than " + std::to_string(kMaxScopeDepth));
      scope.push_back(name);
    } else if (tok == "$upscope") {
      if (!scope.empty()) scope.pop_back();
    } else if (tok == "$var") {
      std::string kind, id, name, range;
      int width = 0;
      ss >> kind >> width >> id >> name >> range;
      if (width <= 0 || id.empty() || name.empty()) throw InputError(vcd_path, lines.where(), "malformed $var");
      if (vars.size() == kMaxVars) throw InputError(vcd_path, lines.where(), "more than " + std::to_string(kMaxVars) + " signals");
      Var v;
      std::string p;
      for (const auto& s : scope) p += s + ".";
      v.path = p + name + (range != "$end" ? range : "");
      v.leaf = name;
      v.width = width;
      // Group: the module below the top (SystemC.arp.<module>), FIFO occupancies together, clocks apart.
      // SystemC.arp.<module>.<signal> in a run; SystemC.<module>.<signal> in a module bench.
      const std::string top_rel = scope.size() >= 3 ? scope[2] : (scope.size() == 2 ? scope[1] : "");
      if (name.find("clk") != std::string::npos || name == "pixel_cycle" || name == "cycle") v.group = "clocks";
      else if (name == "occupancy") v.group = "fifos";
      else v.group = top_rel.empty() ? "top" : top_rel;
      if (name == "occupancy") v.leaf = top_rel + "_occupancy";
      vars.push_back(v);
    }
    // (a line may hold several commands: "$upscope $end $enddefinitions $end")
    for (std::string t = tok; !ended && !t.empty(); t.clear(), ss >> t) ended = t == "$enddefinitions";
    if (ended) break;
  }
  if (vars.empty()) throw InputError(vcd_path, "", "declares no signals");
  // A header that never ends is a file cut short or not a VCD: GTKWave would not open it.
  if (!ended) throw InputError(vcd_path, lines.where(), "the header has no $enddefinitions (cut short, or not a VCD)");
  // Where the view opens: the first timestamp after the header; with no
  // view given, as far as the 200th timestamp (about a hundred clocks: each
  // edge readable) or the end of the trace, whichever comes first.
  int64_t first = -1, last = -1;
  for (int stamps = 0; stamps < 200 && lines.next(line);)
    if (!line.empty() && line[0] == '#') {
      int64_t t = 0;
      const auto [end, ec] = std::from_chars(line.data() + 1, line.data() + line.size(), t);
      if (ec != std::errc() || end != line.data() + line.size() || t < 0 || t < last)
        throw InputError(vcd_path, lines.where(), "'" + quoted(line) + "' is not a timestamp (#N, N >= 0, never decreasing)");
      last = t;
      if (first < 0) first = last;
      ++stamps;
    }
  if (first < 0) first = last = 0;
  if (view <= 0) view = std::max<int64_t>(1, last - first);
  // GTKWave shows 2^-zoom time units per pixel; the wave area is about 1000 pixels of the window below.
  const double zoom = std::clamp(-std::log2(static_cast<double>(view) / kWavePixels), -62.0, 0.0);
  std::map<int, std::map<std::string, std::vector<const Var*>>> groups;
  for (const auto& v : vars) groups[group_rank(v.group)][v.group].push_back(&v);
  std::ostringstream o;
  o << "[*] arpsim waveform view: one group per pipeline stage, in data-flow order\n";
  // Where the view opens (this VCD's window), then the signals (the same for every VCD of a model).
  char z[64];
  std::snprintf(z, sizeof z, "*%.6f -1\n", zoom);
  o << "[timestart] " << first << "\n" << z;
  o << "[dumpfile] \"" << dumpfile << "\"\n";
  o << "[size] 1600 900\n";
  o << "[sst_width] 260\n";
  o << "[signals_width] 320\n";
  for (const auto& [rank, by_name] : groups)
    for (const auto& [g, list] : by_name) {
      o << "@800200\n-" << g << "\n";
      for (const Var* v : list) o << flags_for(*v) << "\n" << v->path << "\n";
      o << "@1000200\n-" << g << "\n";
    }
  return o.str();
}

}  // namespace arp
