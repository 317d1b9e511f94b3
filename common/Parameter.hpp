// A parameter declared once -- key, type, range, unit, one-line doc, and
// where it lives in the structure that holds it (its default is that
// structure's own initial value) -- in a table that the rest is produced
// from: JSON read and write and `--set` (common/ParameterJson), range checks
// (check_ranges), `arpsim config` and the generated tables of
// docs/configuration.md. The model of gem5's Param declarations and VCML's
// property<T>, kept as plain structs so hot paths read plain fields.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace arp {

// A character of printable ASCII (space to '~'): what a TextList parameter with an empty alphabet takes.
inline bool printable_ascii(char ch) { return ch >= ' ' && ch <= '~'; }

// One violated constraint: the dotted key path and the reason.
struct ConfigIssue {
  std::string key;
  std::string reason;
};

// The names of an enum's values, in declaration order: to_string, parse and
// a choice parameter's allowed words all come from one such list.
template <class E>
using EnumNames = std::vector<std::pair<E, const char*>>;

template <class E>
std::string enum_name(const EnumNames<E>& names, E v) {
  for (const auto& [e, n] : names)
    if (e == v) return n;
  return "?";
}
template <class E>
bool enum_parse(const EnumNames<E>& names, const std::string& s, E& out) {
  for (const auto& [e, n] : names)
    if (s == n) {
      out = e;
      return true;
    }
  return false;
}
template <class E>
std::string enum_choices(const EnumNames<E>& names) {  // "a, b, c"
  std::string s;
  for (const auto& [e, n] : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// TextList: a list of strings of any length up to int_max, each of the characters in `alphabet` only (empty:
// any printable ASCII character) (what
// the strings mean is checked where the configuration is validated as a whole). IntegerList: a list of
// integers of any length up to array_size, each in [int_min, int_max] (IntegerArray's length is fixed).
enum class ParamType { Integer, Real, Choice, IntegerArray, RealArray, TextList, IntegerList };

// A parameter's value as readers and writers see it.
using ParamValue = std::variant<int64_t, double, std::string, std::vector<int64_t>, std::vector<double>, std::vector<std::string>>;

template <class Root>
struct Parameter {
  std::string key;  // "section.name"
  ParamType type = ParamType::Integer;
  // Allowed values, inclusive, for numbers and each array element. Choices: the allowed words.
  int64_t int_min = 0, int_max = 0;
  double real_min = 0, real_max = 0;
  std::vector<std::string> choices;
  size_t array_size = 0;  // IntegerArray, RealArray: the length; IntegerList: the longest
  std::string alphabet;  // TextList: the characters its strings may hold
  std::string unit, doc;
  std::function<ParamValue(const Root&)> get;
  // Stores a value already checked against the type and range above.
  std::function<bool(Root&, const ParamValue&)> set;

  std::string section() const { return key.substr(0, key.find('.')); }
  std::string name() const { return key.substr(key.find('.') + 1); }

  // Empty when v is allowed; otherwise why not ("is 40, must be in [1, 28]").
  std::string range_error(const ParamValue& v) const;
  // The allowed range in words, for messages and docs ("1 .. 28", "lut, exact").
  std::string range_text() const;
  // A value as the docs and messages print it.
  static std::string format(const ParamValue& v);
};

// A section's (or a whole configuration's) parameters, in declaration order.
// `ref` arguments locate the field: a generic lambda [](auto& r) -> auto& { return r.a.b; }.
template <class Root>
class ParameterTable {
 public:
  // A number, or a std::array of numbers, each in [lo, hi]; its type comes
  // from the field: integer (read and written as int64_t) when the field is
  // integral, real (double) otherwise.
  template <class Ref, class Lo, class Hi>
  ParameterTable& number(std::string key, Ref ref, Lo lo, Hi hi, std::string unit, std::string doc) {
    using Field = std::remove_reference_t<decltype(ref(std::declval<Root&>()))>;
    if constexpr (std::is_arithmetic_v<Field>) {
      static_assert(!std::is_integral_v<Field> || (std::is_integral_v<Lo> && std::is_integral_v<Hi>),
                    "an integer parameter's range is given in integers");
      using V = std::conditional_t<std::is_integral_v<Field>, int64_t, double>;
      const ParamType t = std::is_integral_v<Field> ? ParamType::Integer : ParamType::Real;
      return add(bounded(scalar<V>(std::move(key), t, ref, std::move(unit), std::move(doc)), static_cast<V>(lo), static_cast<V>(hi)));
    } else {
      using Element = std::remove_const_t<typename Field::value_type>;
      static_assert(!std::is_integral_v<Element> || (std::is_integral_v<Lo> && std::is_integral_v<Hi>),
                    "an integer parameter's range is given in integers");
      using V = std::conditional_t<std::is_integral_v<Element>, int64_t, double>;
      const ParamType t = std::is_integral_v<Element> ? ParamType::IntegerArray : ParamType::RealArray;
      return add(bounded(array<V>(std::move(key), t, ref, std::move(unit), std::move(doc)), static_cast<V>(lo), static_cast<V>(hi)));
    }
  }
  template <class E, class Ref>
  ParameterTable& choice(std::string key, Ref ref, const EnumNames<E>& names, std::string doc) {
    Parameter<Root> p = base(std::move(key), ParamType::Choice, "", std::move(doc));
    for (const auto& [e, n] : names) p.choices.push_back(n);
    p.get = [ref, names](const Root& r) { return ParamValue(enum_name(names, ref(r))); };
    p.set = [ref, names](Root& r, const ParamValue& v) { return enum_parse(names, std::get<std::string>(v), ref(r)); };
    return add(std::move(p));
  }

  // A std::vector<std::string> of at most max_strings strings, each of `alphabet`'s characters only.
  template <class Ref>
  ParameterTable& text_list(std::string key, Ref ref, int64_t max_strings, std::string alphabet, std::string unit, std::string doc) {
    Parameter<Root> p = base(std::move(key), ParamType::TextList, std::move(unit), std::move(doc));
    p.int_min = 0;
    p.int_max = max_strings;
    p.alphabet = std::move(alphabet);
    p.get = [ref](const Root& r) { return ParamValue(ref(r)); };
    p.set = [ref](Root& r, const ParamValue& v) {
      ref(r) = std::get<std::vector<std::string>>(v);
      return true;
    };
    return add(std::move(p));
  }

  // A std::vector<int64_t> of at most max_count integers, each in [lo, hi].
  template <class Ref>
  ParameterTable& number_list(std::string key, Ref ref, size_t max_count, int64_t lo, int64_t hi, std::string unit, std::string doc) {
    Parameter<Root> p = bounded(base(std::move(key), ParamType::IntegerList, std::move(unit), std::move(doc)), lo, hi);
    p.array_size = max_count;
    p.get = [ref](const Root& r) { return ParamValue(ref(r)); };
    p.set = [ref](Root& r, const ParamValue& v) {
      ref(r) = std::get<std::vector<int64_t>>(v);
      return true;
    };
    return add(std::move(p));
  }

  ParameterTable& add(Parameter<Root> p) {
    if (find(p.key)) throw std::logic_error("parameter " + p.key + " declared twice");
    params_.push_back(std::move(p));
    return *this;
  }
  const std::vector<Parameter<Root>>& all() const { return params_; }
  const Parameter<Root>* find(const std::string& key) const {
    for (const auto& p : params_)
      if (p.key == key) return &p;
    return nullptr;
  }
  // Section names in declaration order.
  std::vector<std::string> sections() const {
    std::vector<std::string> s;
    for (const auto& p : params_)
      if (s.empty() || s.back() != p.section()) s.push_back(p.section());
    return s;
  }
  // Every value out of its declared range.
  std::vector<ConfigIssue> check_ranges(const Root& r) const {
    std::vector<ConfigIssue> out;
    for (const auto& p : params_) {
      const std::string e = p.range_error(p.get(r));
      if (!e.empty()) out.push_back({p.key, e});
    }
    return out;
  }

 private:
  static Parameter<Root> bounded(Parameter<Root> p, int64_t lo, int64_t hi) {
    p.int_min = lo;
    p.int_max = hi;
    return p;
  }
  static Parameter<Root> bounded(Parameter<Root> p, double lo, double hi) {
    p.real_min = lo;
    p.real_max = hi;
    return p;
  }
  // A number, read and written as V (int64_t or double) whatever the field's own type.
  template <class V, class Ref>
  static Parameter<Root> scalar(std::string key, ParamType t, Ref ref, std::string unit, std::string doc) {
    Parameter<Root> p = base(std::move(key), t, std::move(unit), std::move(doc));
    p.get = [ref](const Root& r) { return ParamValue(static_cast<V>(ref(r))); };
    p.set = [ref](Root& r, const ParamValue& v) {
      using T = std::remove_reference_t<decltype(ref(r))>;
      ref(r) = static_cast<T>(std::get<V>(v));
      return true;
    };
    return p;
  }
  // A std::array of numbers, read and written as std::vector<V>.
  template <class V, class Ref>
  static Parameter<Root> array(std::string key, ParamType t, Ref ref, std::string unit, std::string doc) {
    Parameter<Root> p = base(std::move(key), t, std::move(unit), std::move(doc));
    p.array_size = std::tuple_size_v<std::remove_reference_t<decltype(ref(std::declval<Root&>()))>>;
    p.get = [ref](const Root& r) {
      const auto& a = ref(r);
      std::vector<V> out;
      for (const auto& e : a) out.push_back(static_cast<V>(e));
      return ParamValue(out);
    };
    p.set = [ref](Root& r, const ParamValue& v) {
      auto& a = ref(r);
      const auto& in = std::get<std::vector<V>>(v);
      for (size_t i = 0; i < a.size(); ++i) a[i] = static_cast<std::remove_reference_t<decltype(a[i])>>(in[i]);
      return true;
    };
    return p;
  }
  static Parameter<Root> base(std::string key, ParamType t, std::string unit, std::string doc) {
    if (key.find('.') == std::string::npos) throw std::logic_error("parameter key without a section: " + key);
    Parameter<Root> p;
    p.key = std::move(key);
    p.type = t;
    p.unit = std::move(unit);
    p.doc = std::move(doc);
    return p;
  }
  std::vector<Parameter<Root>> params_;
};

// Shared by every Parameter<Root>: range messages and value formatting.
namespace param_detail {
std::string range_error(ParamType t, int64_t imin, int64_t imax, double rmin, double rmax,
                        const std::vector<std::string>& choices, size_t array_size, const std::string& alphabet,
                        const ParamValue& v);
std::string range_text(ParamType t, int64_t imin, int64_t imax, double rmin, double rmax,
                       const std::vector<std::string>& choices, const std::string& alphabet, size_t array_size = 0);
std::string format(const ParamValue& v);
}  // namespace param_detail

template <class Root>
std::string Parameter<Root>::range_error(const ParamValue& v) const {
  return param_detail::range_error(type, int_min, int_max, real_min, real_max, choices, array_size, alphabet, v);
}
template <class Root>
std::string Parameter<Root>::range_text() const {
  return param_detail::range_text(type, int_min, int_max, real_min, real_max, choices, alphabet, array_size);
}
template <class Root>
std::string Parameter<Root>::format(const ParamValue& v) {
  return param_detail::format(v);
}

}  // namespace arp
