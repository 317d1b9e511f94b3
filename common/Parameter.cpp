#include "Parameter.hpp"

#include <cmath>
#include <cstdio>

#include "InputError.hpp"

namespace arp::param_detail {

namespace {

// 1000000000 -> "1e9", 1048576 -> "2^20": how the docs write round bounds.
std::string compact(int64_t v) {
  if (v == std::numeric_limits<int64_t>::max()) return "2^63-1";
  if (v >= 10000) {
    int64_t p = v;
    int e = 0;
    while (p % 10 == 0) {
      p /= 10;
      ++e;
    }
    if (p == 1) return "1e" + std::to_string(e);
    if ((v & (v - 1)) == 0) {
      int b = 0;
      while ((int64_t{1} << b) != v) ++b;
      return "2^" + std::to_string(b);
    }
  }
  return std::to_string(v);
}

std::string real_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[64];
  if (v == std::floor(v) && std::abs(v) < 1e15) {
    std::snprintf(b, sizeof b, "%.0f", v);
    return b;
  }
  // The shortest form that reads back the same.
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(b, sizeof b, "%.*g", prec, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

std::string interval(int64_t lo, int64_t hi) { return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; }

std::string real_bounds(double lo, double hi) { return "[" + real_text(lo) + ", " + real_text(hi) + "]"; }

}  // namespace

std::string format(const ParamValue& v) {
  struct {
    std::string operator()(int64_t x) const { return std::to_string(x); }
    std::string operator()(double x) const { return real_text(x); }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
    std::string operator()(const std::vector<int64_t>& a) const {
      std::string s = "[";
      for (size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + std::to_string(a[i]);
      return s + "]";
    }
    std::string operator()(const std::vector<double>& a) const {
      std::string s = "[";
      for (size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + real_text(a[i]);
      return s + "]";
    }
    std::string operator()(const std::vector<std::string>& a) const {
      std::string s = "[";
      for (size_t i = 0; i < a.size(); ++i) s += (i ? ", \"" : "\"") + a[i] + "\"";
      return s + "]";
    }
  } f;
  return std::visit(f, v);
}

std::string range_text(ParamType t, int64_t imin, int64_t imax, double rmin, double rmax,
                       const std::vector<std::string>& choices, const std::string& alphabet, size_t array_size) {
  switch (t) {
    case ParamType::TextList:
      return "up to " + compact(imax) + " strings of " + (alphabet.empty() ? std::string("printable ASCII") : alphabet);
    case ParamType::IntegerList:
      return "up to " + std::to_string(array_size) + " numbers, each " + compact(imin) + " .. " + compact(imax);
    case ParamType::Integer:
    case ParamType::IntegerArray: return compact(imin) + " .. " + compact(imax);
    case ParamType::Real:
    case ParamType::RealArray: return real_text(rmin) + " .. " + real_text(rmax);
    case ParamType::Choice: {
      std::string s;
      for (const auto& c : choices) s += (s.empty() ? "" : ", ") + c;
      return s;
    }
  }
  return "";
}

std::string range_error(ParamType t, int64_t imin, int64_t imax, double rmin, double rmax,
                        const std::vector<std::string>& choices, size_t array_size, const std::string& alphabet,
                        const ParamValue& v) {
  switch (t) {
    case ParamType::TextList: {
      const auto& a = std::get<std::vector<std::string>>(v);
      if (static_cast<int64_t>(a.size()) > imax)
        return "has " + std::to_string(a.size()) + " strings, at most " + std::to_string(imax) + " allowed";
      for (size_t i = 0; i < a.size(); ++i) {
        // An empty alphabet: any printable ASCII character.
        size_t bad = std::string::npos;
        if (alphabet.empty()) {
          for (size_t j = 0; j < a[i].size() && bad == std::string::npos; ++j)
            if (!printable_ascii(a[i][j])) bad = j;
        } else {
          bad = a[i].find_first_not_of(alphabet);
        }
        if (bad != std::string::npos) {
          const unsigned char ch = static_cast<unsigned char>(a[i][bad]);
          char code[8];
          std::snprintf(code, sizeof code, "0x%02x", ch);
          return "string " + std::to_string(i) + " has " +
                 (printable_ascii(static_cast<char>(ch)) ? "\"" + quoted(a[i].substr(bad, 1)) + "\"" : std::string("byte ") + code) + " at character " + std::to_string(bad) +
                 ": only " + (alphabet.empty() ? std::string("printable ASCII") : alphabet) + " allowed";
        }
      }
      return "";
    }
    case ParamType::Integer: {
      const int64_t x = std::get<int64_t>(v);
      if (x < imin || x > imax) return "is " + std::to_string(x) + ", must be in " + interval(imin, imax);
      return "";
    }
    case ParamType::Real: {
      const double x = std::get<double>(v);
      if (!std::isfinite(x)) return "is " + real_text(x) + ", must be a finite number";
      if (x < rmin || x > rmax) return "is " + real_text(x) + ", must be in " + real_bounds(rmin, rmax);
      return "";
    }
    case ParamType::Choice: {
      const std::string& s = std::get<std::string>(v);
      for (const auto& c : choices)
        if (c == s) return "";
      return "is \"" + quoted(s) + "\", must be one of " + range_text(t, 0, 0, 0, 0, choices, alphabet);
    }
    case ParamType::IntegerArray: {
      const auto& a = std::get<std::vector<int64_t>>(v);
      if (a.size() != array_size) return "must have " + std::to_string(array_size) + " elements";
      for (size_t i = 0; i < a.size(); ++i)
        if (a[i] < imin || a[i] > imax)
          return "element " + std::to_string(i) + " is " + std::to_string(a[i]) + ", must be in " + interval(imin, imax);
      return "";
    }
    case ParamType::IntegerList: {
      const auto& a = std::get<std::vector<int64_t>>(v);
      if (a.size() > array_size)
        return "has " + std::to_string(a.size()) + " numbers, at most " + std::to_string(array_size) + " allowed";
      for (size_t i = 0; i < a.size(); ++i)
        if (a[i] < imin || a[i] > imax)
          return "element " + std::to_string(i) + " is " + std::to_string(a[i]) + ", must be in " + interval(imin, imax);
      return "";
    }
    case ParamType::RealArray: {
      const auto& a = std::get<std::vector<double>>(v);
      if (a.size() != array_size) return "must have " + std::to_string(array_size) + " elements";
      for (size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(a[i])) return "element " + std::to_string(i) + " is " + real_text(a[i]) + ", must be a finite number";
        if (a[i] < rmin || a[i] > rmax)
          return "element " + std::to_string(i) + " is " + real_text(a[i]) + ", must be in " + real_bounds(rmin, rmax);
      }
      return "";
    }
  }
  return "";
}

}  // namespace arp::param_detail
