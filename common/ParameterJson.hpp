// A parameter table (common/Parameter.hpp) as JSON and text: write every
// value, read a file or an object strictly (unknown sections and keys, wrong
// types, values out of the declared range: InputError naming the source, the
// key and the reason), `section.key=value` overrides, and the markdown table
// the docs include. One reader for every table: later keys extend a table,
// they do not add a reader.
#pragma once
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "InputError.hpp"
#include "Parameter.hpp"
#include "StrictJson.hpp"

namespace arp {

namespace param_json {
// One JSON value as the parameter's type, or the reason it is not.
bool to_value(ParamType t, size_t array_size, const nlohmann::json& v, ParamValue& out, std::string& why);
nlohmann::json from_value(const ParamValue& v);
// `section.key=value` -> (key, JSON value; a bare word is a string); InputError naming --set otherwise.
std::pair<std::string, nlohmann::json> parse_override(const std::string& s);
}  // namespace param_json

template <class Root>
nlohmann::json parameters_to_json(const ParameterTable<Root>& table, const Root& r) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& p : table.all()) j[p.section()][p.name()] = param_json::from_value(p.get(r));
  return j;
}

// Sets one parameter from a JSON value: type and declared range checked first.
template <class Root>
void set_parameter(const Parameter<Root>& p, const nlohmann::json& v, const std::string& source, Root& r) {
  ParamValue value;
  std::string why;
  if (!param_json::to_value(p.type, p.array_size, v, value, why)) {
    if (p.type == ParamType::Choice) why = "must be one of " + p.range_text() + ", got " + brief(v);
    else if (why.find(" beyond any integer setting") != std::string::npos) why += "; must be in " + p.range_text();
    throw InputError(source, p.key, why);
  }
  const std::string bad = p.range_error(value);
  if (!bad.empty()) throw InputError(source, p.key, bad);
  if (!p.set(r, value)) throw InputError(source, p.key, "must be one of " + p.range_text() + ", got " + brief(v));
}

// Applies the keys present in `j` on top of `r`. Sections the table does not
// declare are refused unless listed in `other_sections` (read by someone else).
template <class Root>
void apply_parameters_json(const ParameterTable<Root>& table, const nlohmann::json& j, const std::string& source, Root& r,
                           const std::vector<std::string>& other_sections = {}) {
  if (!j.is_object()) throw InputError(source, "", "the configuration must be a JSON object, got " + brief(j));
  const auto sections = table.sections();
  std::string known;
  for (const auto& s : sections) known += (known.empty() ? "" : ", ") + s;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const bool ours = std::find(sections.begin(), sections.end(), it.key()) != sections.end();
    if (!ours) {
      if (std::find(other_sections.begin(), other_sections.end(), it.key()) != other_sections.end()) continue;
      throw InputError(source, it.key(), "unknown section (known: " + known + ")");
    }
    if (!it.value().is_object()) throw InputError(source, it.key(), "must be an object, got " + brief(it.value()));
    for (auto k = it.value().begin(); k != it.value().end(); ++k) {
      const Parameter<Root>* p = table.find(it.key() + "." + k.key());
      if (!p) throw InputError(source, it.key() + "." + k.key(), "unknown key");
      set_parameter(*p, k.value(), source, r);
    }
  }
}

// "section.key=value" overrides, in order (later wins); errors name `--set`.
template <class Root>
void apply_parameter_overrides(const ParameterTable<Root>& table, const std::vector<std::string>& sets, Root& r) {
  for (const std::string& s : sets) {
    const auto [key, v] = param_json::parse_override(s);
    const Parameter<Root>* p = table.find(key);
    if (!p) throw InputError("--set", quoted(key), "unknown key (arpsim config --list shows every key)");
    set_parameter(*p, v, "--set", r);
  }
}

// The markdown table of one section: key, default, range, unit, meaning.
template <class Root>
std::string parameters_markdown(const ParameterTable<Root>& table, const std::string& section, const Root& defaults) {
  std::string md = "| key | default | range | unit | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const auto& p : table.all()) {
    if (p.section() != section) continue;
    md += "| `" + p.key + "` | `" + Parameter<Root>::format(p.get(defaults)) + "` | " + p.range_text() + " | " + p.unit +
          " | " + p.doc + " |\n";
  }
  return md;
}

// Every key with its value, range, unit and doc, one per line (`arpsim config --list`).
template <class Root>
std::string parameters_listing(const ParameterTable<Root>& table, const Root& r) {
  std::string s;
  for (const auto& p : table.all())
    s += p.key + " = " + Parameter<Root>::format(p.get(r)) + "  [" + p.range_text() + (p.unit.empty() ? "" : " " + p.unit) +
         "]  " + p.doc + "\n";
  return s;
}

// Replaces each block between "<!-- generated: NAME -->" and "<!-- end generated -->"
// with generate(NAME); the rest of the text is kept as written.
std::string replace_generated_blocks(const std::string& text, const std::function<std::string(const std::string&)>& generate);

}  // namespace arp
