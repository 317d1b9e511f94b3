#include "ParameterJson.hpp"

#include <cmath>

namespace arp {

using nlohmann::json;

namespace param_json {

namespace {

bool integer_of(const json& v, int64_t& out, std::string& why) {
  if (v.is_number_unsigned()) {
    const auto u = v.get<uint64_t>();
    if (u > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) {
      why = "is " + std::to_string(u) + ", beyond any integer setting";  // set_parameter adds the declared range
      return false;
    }
    out = static_cast<int64_t>(u);
    return true;
  }
  if (v.is_number_integer()) {
    out = v.get<int64_t>();
    return true;
  }
  // Digits beyond uint64 reach here as a real number: its size, not its spelling, is the fault.
  if (v.is_number_float() && std::abs(v.get<double>()) >= 0x1p63) {  // (2^63: past int64)
    why = "is " + brief(v) + ", beyond any integer setting";
    return false;
  }
  why = "must be an integer, got " + brief(v);
  // A whole number written with an exponent or a point (1e11, 4.0) is read as a real number: say how to write it.
  if (v.is_number_float() && std::isfinite(v.get<double>()) && std::floor(v.get<double>()) == v.get<double>() &&
      std::abs(v.get<double>()) < 9.2e18)
    why += " (an integer key is written in digits alone: " + std::to_string(static_cast<int64_t>(v.get<double>())) + ")";
  return false;
}

bool real_of(const json& v, double& out, std::string& why) {
  if (!v.is_number()) {
    why = "must be a number, got " + brief(v);
    return false;
  }
  out = v.get<double>();
  return true;
}

}  // namespace

bool to_value(ParamType t, size_t n, const json& v, ParamValue& out, std::string& why) {
  switch (t) {
    case ParamType::Integer: {
      int64_t x = 0;
      if (!integer_of(v, x, why)) return false;
      out = x;
      return true;
    }
    case ParamType::Real: {
      double x = 0;
      if (!real_of(v, x, why)) return false;
      out = x;
      return true;
    }
    case ParamType::TextList: {
      if (!v.is_array()) {
        why = "must be an array of strings, got " + brief(v);
        return false;
      }
      std::vector<std::string> list;
      for (size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_string()) {
          why = "element " + std::to_string(i) + " must be a string, got " + brief(v[i]);
          return false;
        }
        list.push_back(v[i].get<std::string>());
      }
      out = list;
      return true;
    }
    case ParamType::IntegerList: {
      if (!v.is_array()) {
        why = "must be an array of integers, got " + brief(v);
        return false;
      }
      std::vector<int64_t> list;
      for (size_t i = 0; i < v.size(); ++i) {
        std::string w;
        int64_t x = 0;
        if (!integer_of(v[i], x, w)) {
          why = "element " + std::to_string(i) + " " + w;
          return false;
        }
        list.push_back(x);
      }
      out = list;
      return true;
    }
    case ParamType::Choice:
      if (!v.is_string()) return false;
      out = v.get<std::string>();
      return true;
    case ParamType::IntegerArray:
    case ParamType::RealArray: {
      if (!v.is_array() || v.size() != n) {
        why = "must be an array of " + std::to_string(n) + " numbers, got " + brief(v);
        return false;
      }
      std::vector<int64_t> ints;
      std::vector<double> reals;
      for (size_t i = 0; i < n; ++i) {
        std::string w;
        int64_t xi = 0;
        double xr = 0;
        const bool ok = t == ParamType::IntegerArray ? integer_of(v[i], xi, w) : real_of(v[i], xr, w);
        if (!ok) {
          why = "element " + std::to_string(i) + " " + w;
          return false;
        }
        ints.push_back(xi);
        reals.push_back(xr);
      }
      if (t == ParamType::IntegerArray) out = ints;
      else out = reals;
      return true;
    }
  }
  return false;
}

json from_value(const ParamValue& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

std::pair<std::string, json> parse_override(const std::string& s) {
  const auto eq = s.find('=');
  const auto dot = s.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq)
    throw InputError("--set", brief(json(s)), "expected section.key=value, e.g. datapath.vec_frac=12");
  const std::string key = s.substr(0, eq), value = s.substr(eq + 1);
  json v;
  try {
    v = parse_strict_json(value, "--set " + quoted(key));
  } catch (const InputError& e) {
    // A bare word such as half_even is a string; anything that looks like a number or JSON must parse.
    const bool looks_like_json = !value.empty() && (std::string("-+.0123456789[{\"").find(value[0]) != std::string::npos);
    if (looks_like_json) throw InputError("--set", brief(json(key)), e.reason());
    v = value;
  }
  return {key, v};
}

}  // namespace param_json

std::string replace_generated_blocks(const std::string& text, const std::function<std::string(const std::string&)>& generate) {
  static const std::string open = "<!-- generated: ", close = "<!-- end generated -->";
  std::string out;
  size_t pos = 0;
  for (;;) {
    const size_t b = text.find(open, pos);
    if (b == std::string::npos) break;
    const size_t name_end = text.find(" -->", b);
    const size_t e = text.find(close, name_end);
    if (name_end == std::string::npos || e == std::string::npos) break;
    const std::string name = text.substr(b + open.size(), name_end - b - open.size());
    out += text.substr(pos, name_end + 4 - pos) + "\n" + generate(name);
    pos = e;
  }
  return out + text.substr(pos);
}

}  // namespace arp
