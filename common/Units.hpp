// Angles: one constant for pi and the degree conversions every layer uses.
// (Evaluated as deg * pi / 180, left to right, as the code always did: results stay bit-identical.)
// Time: integer picoseconds everywhere.
#pragma once
#include <cmath>
#include <cstdint>

namespace arp {

constexpr int64_t kPsPerSecond = 1'000'000'000'000;
// Picoseconds and seconds as a run converts them: a picosecond time as a double, and a time in seconds to the
// nearest picosecond (the motion's sample held at a time a host asks for).
inline double ps_to_seconds(int64_t ps) { return static_cast<double>(ps) * 1e-12; }
inline int64_t seconds_to_ps(double s) { return static_cast<int64_t>(std::llround(s * 1e12)); }

// How far from the origin objects, eyes, walks and traced heads may be, metres, per coordinate. The
// renderer works relative to the eye in double precision, so a view this far out renders as the same
// view at the origin (tests/ExtremesTest measures it); farther positions are refused where they are read.
constexpr double kWorldLimitM = 1e6;

constexpr double kPi = 3.14159265358979323846;
constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

}  // namespace arp
