#include "StrictJson.hpp"

#include <set>
#include <vector>

#include "InputError.hpp"

namespace arp {

using nlohmann::json;

namespace {

// line:column of a byte offset (1-based), for syntax errors.
std::string position(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// A \u0000 escape decodes to a NUL character, at which every file name and C string ends: "x.obj\u0000y" loaded
// x.obj and "scan\u0000line" was quoted as "scan".
constexpr const char* kNulInString = "a string holding \\u0000 (a NUL character), which no name or setting can hold";

}  // namespace

std::string brief(const json& v) {
  if (v.is_object()) return "an object of " + std::to_string(v.size()) + " keys";
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " elements";
  return quoted(dump_json(v));
}

json parse_strict_json(const std::string& text, const std::string& source) {
  // The parser stops at a NUL byte as if the text ended there: what follows would be ignored.
  if (const size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError(source, position(text, nul + 1), "a NUL byte: binary data, not JSON text");
  // The parser's callback sees every key as it is read: a stack of the keys
  // of the objects open around it finds repeats; depth is checked on the way in.
  std::vector<std::set<std::string>> keys;
  std::vector<std::string> path;
  std::string problem_place, problem;
  auto where = [&] {
    std::string p;
    for (const auto& k : path) p += (p.empty() ? "" : ".") + k;
    return p;
  };
  json::parser_callback_t cb = [&](int depth, json::parse_event_t ev, json& parsed) {
    if (!problem.empty()) return false;
    if (depth > kMaxJsonDepth) {
      problem_place = where();
      problem = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
      throw std::out_of_range(problem);
    }
    switch (ev) {
      case json::parse_event_t::object_start: keys.emplace_back(); break;
      case json::parse_event_t::object_end:
        if (!keys.empty()) keys.pop_back();
        path.resize(keys.size());
        break;
      case json::parse_event_t::key: {
        const std::string k = parsed.get<std::string>();
        path.resize(keys.size());
        path.back() = k;
        if (k.find('\0') != std::string::npos) {
          problem_place = where();
          problem = kNulInString;
          throw std::out_of_range(problem);
        }
        if (!keys.back().insert(k).second) {
          problem_place = where();
          problem = "key given twice in the same object";
          throw std::out_of_range(problem);
        }
        break;
      }
      case json::parse_event_t::value:
        if (parsed.is_string() && parsed.get_ref<const std::string&>().find('\0') != std::string::npos) {
          problem_place = where();
          problem = kNulInString;
          throw std::out_of_range(problem);
        }
        break;
      default: break;
    }
    return true;
  };
  try {
    return json::parse(text, cb);
  } catch (const json::parse_error& e) {
    const std::string what = e.what();
    // nlohmann's text repeats the place ("parse error at line 1, column 14: ..."); the reason alone follows ours.
    const auto at = what.find("parse error");
    const auto colon = at == std::string::npos ? std::string::npos : what.find(": ", at);
    const std::string reason = colon != std::string::npos ? what.substr(colon + 2) : at != std::string::npos ? what.substr(at) : what;
    if (what.find("number overflow") != std::string::npos)
      throw InputError(source, position(text, e.byte), "a number too large for a double (beyond 1.8e308)");
    throw InputError(source, position(text, e.byte), "JSON syntax error: " + quoted(reason));
  } catch (const json::out_of_range& e) {
    // nlohmann reports a number too large for a double this way: find the literal for its place.
    if (problem.empty()) {
      const std::string what = e.what();
      const auto q0 = what.find('\''), q1 = what.rfind('\'');
      const std::string literal = q0 != std::string::npos && q1 > q0 ? what.substr(q0 + 1, q1 - q0 - 1) : "";
      const size_t at = literal.empty() ? std::string::npos : text.find(literal);
      throw InputError(source, at == std::string::npos ? "" : position(text, at + 1),
                       "the number " + quoted(literal) + " is too large for a double (beyond 1.8e308)");
    }
    throw InputError(source, problem_place, problem);
  } catch (const std::out_of_range&) {
    throw InputError(source, problem_place, problem);
  }
}

std::string dump_json(const nlohmann::json& v, int indent) {
  return v.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace arp
