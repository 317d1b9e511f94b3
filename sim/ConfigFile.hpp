// The configuration file (JSON) of the pixel path: every key of
// dp::ArpConfig as declared in dp::arp_parameters(), defaults embedded (the
// struct's own). Reading is strict (common/ParameterJson, common/StrictJson):
// unknown keys, repeated keys, wrong types and out-of-range values are an
// InputError naming the file, the key path and the reason.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::config {

constexpr size_t kMaxConfigBytes = 1 << 20;  // the largest configuration file read (a configuration is a few kB)

nlohmann::json to_json(const dp::ArpConfig& c);

// Applies the keys present in `j` on top of `base`; `source` names the origin in errors.
dp::ArpConfig from_json(const nlohmann::json& j, const std::string& source, dp::ArpConfig base = {});

// Parses and applies a file (syntax errors name line and column).
dp::ArpConfig load_file(const std::string& path, dp::ArpConfig base = {});

// Applies "section.key=value" overrides (value as JSON, or a bare word as a string).
dp::ArpConfig apply_overrides(const dp::ArpConfig& base, const std::vector<std::string>& sets);

// The embedded defaults, then the file (if any), then the overrides (later wins); each key checked as read, the rules
// between keys once on the whole, an error blaming --set, the file, or "FILE with --set" (ConfigFile.cpp).
dp::ArpConfig resolve(const std::string& file, const std::vector<std::string>& sets);

// Throws InputError(source, key, reason) on the first constraint violated.
void check(const dp::ArpConfig& c, const std::string& source);

// docs/configuration.md with its generated tables (one per section) made from
// the parameter table; the prose around them is kept. InputError naming
// source if a section of the table has no generated block in it.
std::string update_reference_doc(const std::string& doc, const std::string& source = "configuration reference");

// Every key with its value, range, unit and doc (`arpsim config --list`).
std::string listing(const dp::ArpConfig& c);

}  // namespace arp::config
