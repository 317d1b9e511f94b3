#include "HardwareCost.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/InputError.hpp"
#include "common/ResourceUsage.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/verilated/HdlConfig.hpp"

namespace arp::sim {

extern const char* const kHdlCostCsv;
extern const char* const kHdlModulesTxt;

namespace {

// The RTL's parameter names (configurations.txt) with this configuration's values.
std::map<std::string, int64_t> rtl_parameters(const dp::ArpConfig& c) {
  const vl::HdlConfig h = vl::hdl_config_of(c);
  return {{"VEC_FRAC", h.vec_frac},         {"MAT_FRAC", h.mat_frac},
          {"ROT_FRAC", h.rot_frac},         {"ROT_ROUNDING", h.rot_rounding},
          {"DIVIDER", h.divider},           {"RECIP_INDEX_BITS", h.recip_index_bits},
          {"RECIP_FRAC_BITS", h.recip_frac_bits}, {"NEWTON_STEPS", h.newton_steps},
          {"QUOT_FRAC", h.quot_frac},       {"DIV_ROUNDING", h.div_rounding},
          {"TEXEL_FRAC", h.texel_frac},     {"TEXEL_ROUNDING", h.texel_rounding},
          {"FACE_SIZE", h.face_size},       {"ROTATE_LATENCY", h.rotate_latency},
          {"ADDRESS_LATENCY", h.address_latency}, {"MEMORIES", h.memories},
          {"RED_BITS", h.red_bits},         {"GREEN_BITS", h.green_bits},
          {"BLUE_BITS", h.blue_bits},       {"DEPTH_BITS", h.depth_bits},
          {"BACKGROUND", h.background},     {"COMPOSE_LATENCY", h.compose_latency},
          {"FILTER_LATENCY", h.filter_latency}};
}

// modules.txt: key -> the configuration value its LATENCY parameter takes.
std::map<std::string, std::string> latency_keys() {
  std::map<std::string, std::string> out;
  std::istringstream in(kHdlModulesTxt);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream l(line);
    std::string key, top, latency;
    if (l >> key >> top >> latency) out[key] = latency;
  }
  return out;
}

// One CSV field list; the parameters column is quoted (it holds spaces, no commas or quotes).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> f(1);
  bool quoted = false;
  for (char ch : line) {
    if (ch == '"') quoted = !quoted;
    else if (ch == ',' && !quoted) f.emplace_back();
    else f.back() += ch;
  }
  return f;
}

struct CostRow {
  SynthesizedModule m;
  std::map<std::string, int64_t> parameters;
};

std::vector<CostRow> cost_rows() {
  std::vector<CostRow> rows;
  std::istringstream in(kHdlCostCsv);
  std::string line;
  std::getline(in, line);  // header: configuration,module,parameters,cells,flip_flops,logic_depth,ice40_lut4,ice40_carry,ice40_ff
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = csv_fields(line);
    if (f.size() < 7) throw std::logic_error("docs/hdl-cost.csv: a row with " + std::to_string(f.size()) + " fields: " + line);
    CostRow r;
    r.m.configuration = f[0];
    r.m.module = f[1];
    r.m.cells = std::stoll(f[3]);
    r.m.flip_flops = std::stoll(f[4]);
    r.m.logic_depth = std::stoll(f[5]);
    r.m.ice40_lut4 = std::stoll(f[6]);
    std::istringstream p(f[2]);
    std::string kv;
    while (p >> kv) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos) throw std::logic_error("docs/hdl-cost.csv: parameter '" + kv + "' without a value");
      r.parameters[kv.substr(0, eq)] = std::stoll(kv.substr(eq + 1));
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

// The bit-count model (see the header): per pixel, the stages the RTL implements.
BitCountModel bit_model(const dp::ArpConfig& c) {
  const dp::DatapathWidths& w = c.widths;
  const int64_t vec = w.vec_frac + 2, mat = w.mat_frac + 2, rot = w.rot_frac + 2;
  const int64_t recip = w.recip_frac_bits + 1, quot = w.quot_frac + 2;
  int64_t face_bits = 0;
  while ((int64_t{1} << face_bits) < c.memory.face_size) ++face_bits;
  BitCountModel m;
  // Orientation matrix unit: nine products, two sums per row, three roundings.
  m.multiplier_bits += 9 * vec * mat;
  m.adder_bits += 3 * 2 * (vec + mat) + 3 * rot;
  // Address generator: three magnitude compares; the divider; two texel scalings.
  m.adder_bits += 3 * rot;
  if (w.divider == dp::DividerKind::ReciprocalLut) {
    m.table_bits += (int64_t{1} << w.recip_index_bits) * recip;
    m.multiplier_bits += w.newton_steps * 2 * recip * recip + 2 * rot * recip;
  } else {
    m.adder_bits += 2 * quot * (rot + 1);  // two restoring dividers: one subtract per quotient bit
  }
  m.multiplier_bits += 2 * quot * face_bits;
  m.adder_bits += 2 * (face_bits + w.texel_frac);
  // Composition: per tap, a compare per extra memory; bilinear composites four taps.
  const int64_t taps = c.pipeline.aa == dp::AaMode::Bilinear ? 4 : 1;
  m.adder_bits += taps * (c.memory.count - 1) * c.memory.depth_bits;
  // Filter: three channels, four weighted taps (the weights' products), three sums.
  if (taps == 4) {
    const int64_t weight = 2 * (w.texel_frac + 1);
    m.multiplier_bits += 4 * (w.texel_frac + 1) * (w.texel_frac + 1) + 4 * c.memory.color_bits() * weight;
    m.adder_bits += 3 * c.memory.color_bits() + c.memory.color_bits() * weight / 2;
  }
  return m;
}

}  // namespace

bool HardwareCost::fully_synthesized() const { return synthesized.size() == rtl_module_keys().size(); }
int64_t HardwareCost::cells() const {
  int64_t n = 0;
  for (const auto& s : synthesized) n += s.cells;
  return n;
}
int64_t HardwareCost::lut4() const {
  int64_t n = 0;
  for (const auto& s : synthesized) n += s.ice40_lut4;
  return n;
}
int64_t HardwareCost::logic_depth() const {
  int64_t d = 0;
  for (const auto& s : synthesized) d = std::max(d, s.logic_depth);
  return d;
}
std::string HardwareCost::configuration() const {
  if (synthesized.empty()) return "";
  std::string name = synthesized.front().configuration;
  for (const auto& s : synthesized)
    if (s.configuration != name) return "mixed";
  return name;
}

std::vector<std::string> rtl_module_keys() {
  std::vector<std::string> keys;
  for (const auto& [k, latency] : latency_keys()) keys.push_back(k);
  return keys;
}

std::vector<SynthesizedModule> synthesized_rows() {
  std::vector<SynthesizedModule> out;
  for (const auto& r : cost_rows()) out.push_back(r.m);
  return out;
}

HardwareCost hardware_cost(const dp::ArpConfig& c) {
  HardwareCost cost;
  cost.model = bit_model(c);
  const auto values = rtl_parameters(c);
  const auto latency = latency_keys();
  std::map<std::string, bool> taken;
  for (const auto& r : cost_rows()) {
    if (taken[r.m.module]) continue;  // several configurations may share one module's parameters
    const auto latency_key = latency.find(r.m.module);
    if (latency_key == latency.end()) continue;
    bool same = true;
    for (const auto& [name, v] : r.parameters) {
      const std::string key = name == "LATENCY" ? latency_key->second : name;
      const auto it = values.find(key);
      if (it == values.end() || it->second != v) {
        same = false;
        break;
      }
    }
    if (!same) continue;
    taken[r.m.module] = true;
    cost.synthesized.push_back(r.m);
  }
  return cost;
}

std::string hardware_cost_source() {
  const auto rows = cost_rows();
  std::vector<std::string> names;
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), r.m.configuration) == names.end()) names.push_back(r.m.configuration);
  std::string s = "docs/hdl-cost.csv (scripts/hdl-cost.sh: yosys generic synth and synth_ice40; no timing closure, no place "
                  "and route): " + std::to_string(rows.size()) + " module syntheses of " + std::to_string(names.size()) +
                  " configurations (";
  for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s + ")";
}

namespace {

// The cube-face renderer's faces at face size S (host::CubeFaceRenderer), bytes.
int64_t renderer_bytes(int64_t S) { return 6 * S * S * (36 + 8) + 2 * S * S * 8; }

std::string gb_text(int64_t b) {
  char t[32];
  std::snprintf(t, sizeof t, "%.1f GB", static_cast<double>(b) / 1e9);
  return t;
}

}  // namespace

void check_plan_fits_memory(int face_size, int eyes, const std::string& place, const std::string& key, const std::string& why) {
  const int64_t available = available_memory_bytes();
  if (available <= 0) return;
  const int64_t S = face_size, tiles = dp::DisplayMemoryBank::tiles_per_row_of(face_size);
  const int64_t bank = int64_t{eyes} * 2 * (6 * tiles * tiles + 1) * dp::DisplayMemoryBank::kTileWords * 8;
  const int64_t need = renderer_bytes(S) + bank;
  if (need <= available) return;
  throw InputError(place, key,
                   "a plan renders the scene at face size " + std::to_string(face_size) + " (" + why + "): that may need up to " +
                       gb_text(need) + " (the renderer's faces " + gb_text(renderer_bytes(S)) + ", a display memory " + gb_text(bank) +
                       "), more than the " + gb_text(available) + " this process has available");
}

void check_model_fits_memory(const dp::ArpConfig& c, const std::string& config_source, bool draws_scene, int truth_face_size) {
  const int64_t available = available_memory_bytes();
  if (available <= 0) return;  // not known: nothing to compare with
  auto memories = [&](int64_t S, int count, int faces) {
    const int64_t tiles = dp::DisplayMemoryBank::tiles_per_row_of(static_cast<int>(S));
    return int64_t{c.timing.eyes} * count * 2 * (faces * tiles * tiles + 1) * dp::DisplayMemoryBank::kTileWords * 8;
  };
  const auto renderer = renderer_bytes;
  const int64_t S = c.memory.face_size, T = truth_face_size > 0 ? truth_face_size : S;
  const int64_t own = memories(S, c.memory.count, c.memory.faces_present()), faces = draws_scene ? renderer(S) : 0;
  const int64_t truth = truth_face_size >= 0 ? memories(T, 1, 6) + renderer(T) + int64_t{c.timing.eyes} * 6 * T * T * 4 : 0;
  // The display's side: the frame being scanned out, its photon times, the lens table, the models' own
  // frames. Measured on 2026-11-29 at 2 x 2048 x 2048 against 2 x 640 x 480 (peak RSS): 24 bytes a display
  // pixel more at the functional and loosely timed levels, 29 at the detailed level, 45 at the fast cycle level.
  constexpr int64_t kDisplayBytesPerPixel = 48;
  const int64_t display = int64_t{c.timing.eyes} * c.timing.h_active * c.timing.v_active * kDisplayBytesPerPixel;
  if (own + faces + truth + display <= available) return;
  const auto gb = gb_text;
  const int64_t total = own + faces + truth + display;
  const std::string parts = " (display memories with every tile written " + gb(own) + (draws_scene ? ", the renderer's faces " + gb(faces) : "") +
                            (truth_face_size >= 0 ? ", the truth's memory and faces " + gb(truth) : "") + ", the display's frames " +
                            gb(display) + "), more than the " + gb(available) + " this process has available";
  if (display > own + faces + truth)
    throw InputError(config_source, "display.h_active",
                     "a run of a " + std::to_string(c.timing.h_active) + " x " + std::to_string(c.timing.v_active) + " display may need up to " +
                         gb(total) + parts + ": a smaller display");
  const bool truths = truth_face_size > 0 && truth > own + faces;
  throw InputError(truths ? "--truth-face-size" : config_source, truths ? std::to_string(T) : "memory.face_size",
                   "a run at face size " + std::to_string(truths ? T : S) + " may need up to " + gb(total) + parts +
                       ": a smaller face size or fewer memories");
}

namespace {

// A tile table's bits: an entry per tile of each face present, numbering `n` slots and "absent".
int64_t tile_table_bits(const dp::ArpConfig& c, int64_t n) {
  const int64_t tpr = dp::DisplayMemoryBank::tiles_per_row_of(c.memory.face_size);
  int entry = 0;
  while ((int64_t{1} << entry) <= n) ++entry;
  return int64_t{c.memory.faces_present()} * tpr * tpr * entry;
}

// `n` tile slots' texels.
int64_t slot_bits(const dp::ArpConfig& c, int64_t n) {
  constexpr int64_t kTile = dp::DisplayMemoryBank::kTile;
  return n * kTile * kTile * (int64_t{c.memory.color_bits()} + c.memory.depth_bits);
}

}  // namespace

int64_t bank_bits_tiled(const dp::ArpConfig& c, int64_t n) { return 2 * slot_bits(c, n) + tile_table_bits(c, n); }

int64_t bank_bits_pooled(const dp::ArpConfig& c, int64_t slots) { return slot_bits(c, slots) + 2 * tile_table_bits(c, slots); }

namespace {

// tiles_held for every memory, the list parsed once.
std::vector<int64_t> tiles_held_all(const dp::ArpConfig& c) {
  std::vector<dp::TileMap> maps;
  if (std::string why; !dp::tile_maps(c.memory, maps, why)) throw std::invalid_argument("memory.tiles " + why);
  const dp::MemoryFormat fmt(c.memory);
  std::vector<int64_t> held;
  for (const dp::TileMap& map : maps) {
    if (map.every_tile(fmt.present)) {
      held.push_back(-1);
      continue;
    }
    int64_t n = 0;
    for (int f = 0; f < 6; ++f)
      if (fmt.present[static_cast<size_t>(f)]) n += map.tiles(f);
    held.push_back(n);
  }
  return held;
}

}  // namespace

int64_t tiles_held(const dp::ArpConfig& c, int memory) { return tiles_held_all(c).at(static_cast<size_t>(memory)); }

int64_t bank_bits_whole(const dp::ArpConfig& c) {
  const int64_t S = c.memory.face_size;
  return 2 * int64_t{c.memory.faces_present()} * S * S * (int64_t{c.memory.color_bits()} + c.memory.depth_bits);
}

int64_t display_memory_bytes(const dp::ArpConfig& c) {
  const int64_t whole_memory_bits = int64_t{c.timing.eyes} * bank_bits_whole(c);
  int64_t total_bits = 0;
  bool sparse = false;
  const std::vector<int64_t> held = tiles_held_all(c);
  for (int k = 0; k < c.memory.count; ++k) {
    const int64_t n = held[static_cast<size_t>(k)], slots = c.memory.pool_slots(k);
    sparse |= n >= 0 || slots > 0;
    total_bits += slots > 0 ? c.timing.eyes * bank_bits_pooled(c, slots) : n < 0 ? whole_memory_bits : c.timing.eyes * bank_bits_tiled(c, n);
  }
  return sparse ? (total_bits + 7) / 8 : total_bits / 8;
}

int64_t display_memory_bytes_tiled(const dp::ArpConfig& c, const std::vector<int64_t>& tiles) {
  int64_t total_bits = 0;
  for (const int64_t n : tiles) total_bits += bank_bits_tiled(c, n);
  return (total_bits + 7) / 8;
}

bool tiles_take_less(const dp::ArpConfig& c, int64_t tiles) { return bank_bits_tiled(c, tiles) < bank_bits_whole(c); }

int64_t display_memory_bytes_pooled(const dp::ArpConfig& c, const dp::DisplayMemorySet& m) {
  int64_t bits = 0;
  for (int e = 0; e < m.eyes(); ++e)
    for (int k = 0; k < m.count(); ++k) bits += bank_bits_pooled(c, m.bank(e, k).tiles_most_at_once());
  return (bits + 7) / 8;
}

int64_t display_memory_bytes_tiled(const dp::ArpConfig& c, const dp::DisplayMemorySet& m) {
  std::vector<int64_t> tiles;
  for (int e = 0; e < m.eyes(); ++e)
    for (int k = 0; k < m.count(); ++k) tiles.push_back(m.bank(e, k).tiles_ever_written());
  return display_memory_bytes_tiled(c, tiles);
}

}  // namespace arp::sim
