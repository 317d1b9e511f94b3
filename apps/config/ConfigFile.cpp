#include "ConfigFile.hpp"

#include <fstream>
#include <limits>
#include <type_traits>
#include <set>
#include <sstream>

#include "common/InputError.hpp"

namespace arp::config {

using nlohmann::json;
using namespace arp::dp;

namespace {
json timed_json(const TimedConfig& tm) {
  json j = json::object();
  for (int s = 0; s < kStageCount; ++s) {
    const std::string k = stage_key(static_cast<Stage>(s));
    j[k + "_latency"] = tm.stage[static_cast<size_t>(s)].latency_cycles;
    j[k + "_logic_ps"] = tm.stage[static_cast<size_t>(s)].logic_delay_ps;
  }
  j["fifo_depth"] = tm.fifo_depth;
  j["issue_slack_cycles"] = tm.issue_slack_cycles;
  j["host_clock_hz"] = tm.host_clock_hz;
  j["host_texels_per_cycle"] = tm.host_texels_per_cycle;
  return j;
}
}  // namespace

json to_json(const ArpConfig& c) {
  const auto& t = c.timing;
  const auto& l = c.lens;
  const auto& w = c.widths;
  const auto& m = c.memory;
  const auto& p = c.pipeline;
  return json{
      {"display",
       {{"eyes", t.eyes}, {"eye_scan", to_string(t.eye_scan)}, {"h_active", t.h_active},
        {"h_front_porch", t.h_front_porch}, {"h_sync", t.h_sync}, {"h_back_porch", t.h_back_porch},
        {"v_active", t.v_active}, {"v_front_porch", t.v_front_porch}, {"v_sync", t.v_sync},
        {"v_back_porch", t.v_back_porch}, {"pixel_clock_hz", t.pixel_clock_hz}, {"fields_per_frame", t.fields_per_frame}}},
      {"lens", {{"fov_deg", l.fov_deg}, {"k", l.k}, {"center_offset_px", l.center_offset_px}}},
      {"datapath",
       {{"vec_frac", w.vec_frac}, {"mat_frac", w.mat_frac}, {"rot_frac", w.rot_frac},
        {"rot_rounding", to_string(w.rot_rounding)}, {"divider", to_string(w.divider)},
        {"recip_index_bits", w.recip_index_bits}, {"recip_frac_bits", w.recip_frac_bits},
        {"newton_steps", w.newton_steps}, {"quot_frac", w.quot_frac}, {"div_rounding", to_string(w.div_rounding)},
        {"texel_frac", w.texel_frac}, {"texel_rounding", to_string(w.texel_rounding)}}},
      {"memory",
       {{"count", m.count}, {"face_size", m.face_size}, {"red_bits", m.red_bits}, {"green_bits", m.green_bits},
        {"blue_bits", m.blue_bits}, {"depth_bits", m.depth_bits}, {"background", m.background}}},
      {"pipeline",
       {{"latch", to_string(p.latch)}, {"latch_lead_cycles", p.latch_lead_cycles}, {"aa", to_string(p.aa)},
        {"display_bits", p.display_bits}, {"photon_delay_ps", p.photon_delay_ps}}},
      {"timed", timed_json(c.timed)},
  };
}

namespace {

// Reads one object section, remembering which keys it consumed.
class Section {
 public:
  Section(const json& root, const char* name, const std::string& source) : name_(name), source_(source) {
    if (!root.contains(name)) return;
    obj_ = &root.at(name);
    if (!obj_->is_object()) fail("", "must be an object");
  }
  template <typename Int>
  void integer(const char* key, Int& out) {
    const json* v = get(key);
    if (!v) return;
    if (!v->is_number_integer()) fail(key, "must be an integer, got " + v->dump());
    const int64_t x = v->get<int64_t>();
    if (x < static_cast<int64_t>(std::numeric_limits<Int>::min()) || x > static_cast<int64_t>(std::numeric_limits<Int>::max()))
      fail(key, "value " + v->dump() + " is out of range");
    out = static_cast<Int>(x);
  }
  void real(const char* key, double& out) {
    const json* v = get(key);
    if (!v) return;
    if (!v->is_number()) fail(key, "must be a number, got " + v->dump());
    out = v->get<double>();
  }
  template <typename E>
  void word(const char* key, E& out, const char* choices) {
    const json* v = get(key);
    if (!v) return;
    if (!v->is_string() || !parse(v->get<std::string>(), out)) fail(key, "must be one of " + std::string(choices) + ", got " + v->dump());
  }
  void rounding(const char* key, Rounding& out) {
    const json* v = get(key);
    if (!v) return;
    if (!v->is_string() || !parse_rounding(v->get<std::string>(), out))
      fail(key, "must be one of floor, half_up, half_even, got " + v->dump());
  }
  template <typename T, size_t N>
  void array(const char* key, std::array<T, N>& out) {
    const json* v = get(key);
    if (!v) return;
    if (!v->is_array() || v->size() != N) fail(key, "must be an array of " + std::to_string(N) + " numbers");
    for (size_t i = 0; i < N; ++i) {
      const json& e = (*v)[i];
      if constexpr (std::is_integral_v<T>) {
        if (!e.is_number_integer()) fail(key, "element " + std::to_string(i) + " must be an integer");
      } else if (!e.is_number()) {
        fail(key, "element " + std::to_string(i) + " must be a number");
      }
      out[i] = e.get<T>();
    }
  }
  void finish() {
    if (!obj_) return;
    for (auto it = obj_->begin(); it != obj_->end(); ++it)
      if (!seen_.count(it.key())) fail(it.key().c_str(), "unknown key");
  }

 private:
  const json* get(const char* key) {
    seen_.insert(key);
    if (!obj_ || !obj_->contains(key)) return nullptr;
    return &obj_->at(key);
  }
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw InputError(source_, key.empty() ? name_ : name_ + "." + key, reason);
  }
  std::string name_;
  const std::string& source_;
  const json* obj_ = nullptr;
  std::set<std::string> seen_;
};

}  // namespace

void check(const ArpConfig& c, const std::string& source) {
  const auto issues = validate(c);
  if (!issues.empty()) throw InputError(source, issues.front().key, issues.front().reason);
}

ArpConfig from_json(const json& j, const std::string& source, ArpConfig c) {
  if (!j.is_object()) throw InputError(source, "", "the configuration must be a JSON object");
  static const std::set<std::string> sections{"display", "lens", "datapath", "memory", "pipeline", "timed"};
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!sections.count(it.key()))
      throw InputError(source, it.key(), "unknown section (known: display, lens, datapath, memory, pipeline, timed)");
  {
    auto& t = c.timing;
    Section s(j, "display", source);
    s.integer("eyes", t.eyes);
    s.word("eye_scan", t.eye_scan, "lockstep, side_by_side");
    s.integer("h_active", t.h_active);
    s.integer("h_front_porch", t.h_front_porch);
    s.integer("h_sync", t.h_sync);
    s.integer("h_back_porch", t.h_back_porch);
    s.integer("v_active", t.v_active);
    s.integer("v_front_porch", t.v_front_porch);
    s.integer("v_sync", t.v_sync);
    s.integer("v_back_porch", t.v_back_porch);
    s.integer("pixel_clock_hz", t.pixel_clock_hz);
    s.integer("fields_per_frame", t.fields_per_frame);
    s.finish();
  }
  {
    auto& l = c.lens;
    Section s(j, "lens", source);
    s.real("fov_deg", l.fov_deg);
    s.array("k", l.k);
    s.real("center_offset_px", l.center_offset_px);
    s.finish();
  }
  {
    auto& w = c.widths;
    Section s(j, "datapath", source);
    s.integer("vec_frac", w.vec_frac);
    s.integer("mat_frac", w.mat_frac);
    s.integer("rot_frac", w.rot_frac);
    s.rounding("rot_rounding", w.rot_rounding);
    s.word("divider", w.divider, "lut, exact");
    s.integer("recip_index_bits", w.recip_index_bits);
    s.integer("recip_frac_bits", w.recip_frac_bits);
    s.integer("newton_steps", w.newton_steps);
    s.integer("quot_frac", w.quot_frac);
    s.rounding("div_rounding", w.div_rounding);
    s.integer("texel_frac", w.texel_frac);
    s.rounding("texel_rounding", w.texel_rounding);
    s.finish();
  }
  {
    auto& m = c.memory;
    Section s(j, "memory", source);
    s.integer("count", m.count);
    s.integer("face_size", m.face_size);
    s.integer("red_bits", m.red_bits);
    s.integer("green_bits", m.green_bits);
    s.integer("blue_bits", m.blue_bits);
    s.integer("depth_bits", m.depth_bits);
    s.array("background", m.background);
    s.finish();
  }
  {
    auto& p = c.pipeline;
    Section s(j, "pipeline", source);
    s.word("latch", p.latch, "frame, field, scanline, pixel");
    s.integer("latch_lead_cycles", p.latch_lead_cycles);
    s.word("aa", p.aa, "off, bilinear");
    s.integer("display_bits", p.display_bits);
    s.integer("photon_delay_ps", p.photon_delay_ps);
    s.finish();
  }
  {
    auto& tm = c.timed;
    Section s(j, "timed", source);
    for (int k = 0; k < kStageCount; ++k) {
      const std::string name = stage_key(static_cast<Stage>(k));
      s.integer((name + "_latency").c_str(), tm.stage[static_cast<size_t>(k)].latency_cycles);
      s.integer((name + "_logic_ps").c_str(), tm.stage[static_cast<size_t>(k)].logic_delay_ps);
    }
    s.integer("fifo_depth", tm.fifo_depth);
    s.integer("issue_slack_cycles", tm.issue_slack_cycles);
    s.integer("host_clock_hz", tm.host_clock_hz);
    s.integer("host_texels_per_cycle", tm.host_texels_per_cycle);
    s.finish();
  }
  check(c, source);
  return c;
}

ArpConfig load_file(const std::string& path, ArpConfig base) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the configuration file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line:column for the user.
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    std::string what = e.what();
    const auto pos = what.find("parse error");
    throw InputError(path, "line " + std::to_string(line) + ", column " + std::to_string(col),
                     "JSON syntax error: " + (pos == std::string::npos ? what : what.substr(pos)));
  }
  return from_json(j, path, base);
}

ArpConfig apply_overrides(const ArpConfig& base, const std::vector<std::string>& sets) {
  json j = json::object();
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    const auto dot = s.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq)
      throw InputError("--set " + s, "", "expected section.key=value, e.g. datapath.vec_frac=12");
    const std::string section = s.substr(0, dot), key = s.substr(dot + 1, eq - dot - 1), value = s.substr(eq + 1);
    json v;
    try {
      v = json::parse(value);
    } catch (const json::parse_error&) {
      v = value;  // a bare word such as half_even
    }
    j[section][key] = v;
  }
  return from_json(j, "--set", base);
}

}  // namespace arp::config
