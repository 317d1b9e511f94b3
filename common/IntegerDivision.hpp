// Integer division rounded towards minus infinity (C++'s / rounds towards zero): which frame, line or period a
// count falls in when the count can be negative (before the first swap, before the run's first frame).
#pragma once
#include <cstdint>

namespace arp {

constexpr int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0); }

}  // namespace arp
