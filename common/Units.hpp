// Angles: one constant for pi and the degree conversions every layer uses.
// (Evaluated as deg * pi / 180, left to right, as the code always did: results stay bit-identical.)
// Time: integer picoseconds everywhere.
#pragma once
#include <cstdint>

namespace arp {

constexpr int64_t kPsPerSecond = 1'000'000'000'000;

constexpr double kPi = 3.14159265358979323846;
constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

}  // namespace arp
