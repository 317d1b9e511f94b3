// Reading JSON that users write (configurations, scenes, walks) strictly:
// a syntax error names line and column; a key given twice in one object, a
// number too large for a double and nesting deeper than kMaxDepth are errors
// too (never "last one wins", never a crash). Messages quote at most
// kQuoteChars of a value (common/InputError.hpp, brief()).
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "InputFile.hpp"  // read_input_file: the text these parse

namespace arp {

constexpr int kMaxJsonDepth = 64;

// Parses `text` read from `source`; InputError(source, "line L, column C" or the key path, reason).
nlohmann::json parse_strict_json(const std::string& text, const std::string& source);

// A value as an error message quotes it: at most kQuoteChars characters.
std::string brief(const nlohmann::json& v);

// JSON as text for every file and message arpsim writes: a string holding
// bytes that are not UTF-8 (a file name, a --set value) is written with
// U+FFFD in their place instead of throwing. indent < 0: one line.
std::string dump_json(const nlohmann::json& v, int indent = -1);

}  // namespace arp
