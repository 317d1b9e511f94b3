// The one error type for bad input anywhere in arpsim: it names the source
// (file, option, device), the place inside it, and the reason.
#pragma once
#include <stdexcept>
#include <string>

namespace arp {

// A message quotes at most this much of a bad value: enough to recognise it,
// never a flood (a 10 MB field, a binary file read as text).
constexpr size_t kQuoteChars = 80;
inline std::string quoted(std::string s) {
  if (s.size() > kQuoteChars) s = s.substr(0, kQuoteChars - 3) + "...";
  return s;
}

class InputError : public std::runtime_error {
 public:
  // The place is quoted (at most kQuoteChars): it can come from the input itself (a JSON key, a --set
  // key), and a message must never become a flood.
  InputError(std::string source, std::string place, std::string reason)
      : std::runtime_error(compose(source, quoted(place), reason)),
        source_(std::move(source)), place_(quoted(std::move(place))), reason_(std::move(reason)) {}
  const std::string& source() const { return source_; }
  const std::string& place() const { return place_; }
  const std::string& reason() const { return reason_; }

 private:
  static std::string compose(const std::string& s, const std::string& p, const std::string& r) {
    std::string m = s.empty() ? std::string("input") : s;
    if (!p.empty()) m += ": " + p;
    return m + ": " + r;
  }
  std::string source_, place_, reason_;
};

}  // namespace arp
