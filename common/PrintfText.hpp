// One double through a printf format ("%.3f", "%.1f %%"): the text of a figure in a report or summary.
#pragma once
#include <cstdio>
#include <string>

namespace arp {

inline std::string printf_text(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}  // namespace arp
