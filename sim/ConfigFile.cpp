#include "ConfigFile.hpp"

#include <algorithm>
#include <set>

#include "common/InputError.hpp"
#include "common/ParameterJson.hpp"
#include "common/StrictJson.hpp"

namespace arp::config {

using nlohmann::json;

namespace {
// A configuration file's JSON, read strictly (syntax errors name line and column).
json read_file_json(const std::string& path) {
  return parse_strict_json(read_input_file(path, kMaxConfigBytes, "configuration file"), path);
}
}  // namespace

json to_json(const dp::ArpConfig& c) { return parameters_to_json(dp::arp_parameters(), c); }

void check(const dp::ArpConfig& c, const std::string& source) {
  const auto issues = dp::validate(c);
  if (!issues.empty()) throw InputError(source, issues.front().key, issues.front().reason);
}

dp::ArpConfig from_json(const json& j, const std::string& source, dp::ArpConfig c) {
  apply_parameters_json(dp::arp_parameters(), j, source, c);
  check(c, source);
  return c;
}

dp::ArpConfig load_file(const std::string& path, dp::ArpConfig base) {
  return from_json(read_file_json(path), path, base);
}

dp::ArpConfig apply_overrides(const dp::ArpConfig& base, const std::vector<std::string>& sets) {
  dp::ArpConfig c = base;
  apply_parameter_overrides(dp::arp_parameters(), sets, c);
  check(c, "--set");
  return c;
}

// The file and the overrides are one configuration: each key is checked as it is read, the rules between keys
// once, on the whole (a file may hold a value only its --set makes valid: texel_frac 0 with --set pipeline.aa=off).
// A rule broken is blamed on --set when an override named its key; else on the file when the file alone breaks a
// rule; else on both (the file was fine until an override changed another key the rule reads).
dp::ArpConfig resolve(const std::string& file, const std::vector<std::string>& sets) {
  dp::ArpConfig c;
  if (!file.empty()) apply_parameters_json(dp::arp_parameters(), read_file_json(file), file, c);
  const dp::ArpConfig from_file = c;
  apply_parameter_overrides(dp::arp_parameters(), sets, c);
  const auto issues = dp::validate(c);
  if (issues.empty()) return c;
  const dp::ConfigIssue& first = issues.front();
  const bool set_named_it = std::any_of(sets.begin(), sets.end(), [&](const std::string& s) {
    return s.compare(0, first.key.size() + 1, first.key + "=") == 0;
  });
  if (sets.empty() || (!file.empty() && !set_named_it && !dp::validate(from_file).empty()))
    throw InputError(file.empty() ? std::string("configuration") : file, first.key, first.reason);
  throw InputError(file.empty() || set_named_it ? std::string("--set") : file + " with --set", first.key, first.reason);
}

std::string update_reference_doc(const std::string& doc, const std::string& source) {
  const dp::ArpConfig defaults;
  std::set<std::string> generated;
  const std::string updated = replace_generated_blocks(doc, [&](const std::string& section) {
    generated.insert(section);
    return parameters_markdown(dp::arp_parameters(), section, defaults);
  });
  // A section without its table would leave its keys undocumented, and "current" would be a lie.
  for (const std::string& section : dp::arp_parameters().sections())
    if (!generated.count(section))
      throw InputError(source, "", "has no table for the keys of section '" + section + "': add a line '<!-- generated: " +
                                       section + " -->' and a line '<!-- end generated -->' where it belongs, then run again");
  return updated;
}

std::string listing(const dp::ArpConfig& c) { return parameters_listing(dp::arp_parameters(), c); }

}  // namespace arp::config
