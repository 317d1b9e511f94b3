// A whole number written in decimal, read strictly: the whole text, an optional sign, digits only, within
// int64_t (a value beyond it is no number, not a wrapped one).
#pragma once
#include <charconv>
#include <cstdint>
#include <optional>
#include <string_view>

namespace arp {

inline std::optional<int64_t> whole_number(std::string_view s) {
  if (!s.empty() && s[0] == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s[0] == '-') return std::nullopt;  // ("+-5")
  }
  const size_t digits = !s.empty() && s[0] == '-' ? 1 : 0;
  if (s.size() == digits || s.find_first_not_of("0123456789", digits) != std::string_view::npos) return std::nullopt;
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace arp
