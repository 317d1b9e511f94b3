// Fixed-point primitives shared by every datapath stage. Widths and rounding
// are run-time values so a width sweep needs no rebuild; every function is
// branch-free so the functional model's loops can vectorise.
#pragma once
#include <cstdint>
#include <string>

#include "common/Parameter.hpp"

namespace arp::dp {

// How a right shift (dropping fraction bits) rounds.
enum class Rounding : uint8_t {
  Floor,     // two's-complement truncation (toward -inf): the cheapest hardware
  HalfUp,    // round to nearest, ties toward +inf: one adder
  HalfEven,  // round to nearest, ties to even: unbiased
};

const EnumNames<Rounding>& rounding_names();  // floor, half_up, half_even
inline std::string to_string(Rounding r) { return enum_name(rounding_names(), r); }
inline bool parse_rounding(const std::string& s, Rounding& out) { return enum_parse(rounding_names(), s, out); }

// Precomputed constants of a rounding shift so the per-pixel cost is a few
// branch-free operations: r = ((v << left) + bias + (((v << left) >> right) & even)) >> right.
// A negative shift amount is an exact left shift.
struct RoundShift {
  int left = 0, right = 0;
  int64_t bias = 0;
  int64_t even = 0;  // 1 for HalfEven, else 0

  RoundShift() = default;
  RoundShift(int shift_bits, Rounding mode)
      : left(shift_bits < 0 ? -shift_bits : 0), right(shift_bits > 0 ? shift_bits : 0) {
    if (right == 0) return;
    const int64_t half = int64_t{1} << (right - 1);
    switch (mode) {
      case Rounding::Floor: bias = 0; break;
      case Rounding::HalfUp: bias = half; break;
      case Rounding::HalfEven: bias = half - 1; even = 1; break;
    }
  }
  constexpr int64_t apply(int64_t v) const {
    const int64_t w = static_cast<int64_t>(static_cast<uint64_t>(v) << left);
    return (w + bias + ((w >> right) & even)) >> right;
  }
};

// Saturation to a signed two's-complement width (bits includes the sign).
struct SignedRange {
  int64_t lo = 0, hi = 0;
  SignedRange() = default;
  explicit SignedRange(int bits)
      : lo(-(int64_t{1} << (bits - 1))), hi((int64_t{1} << (bits - 1)) - 1) {}
  constexpr int64_t clamp(int64_t v) const {
    const int64_t a = v > lo ? v : lo;  // written as max then min so loops vectorise
    return a < hi ? a : hi;
  }
  constexpr bool contains(int64_t v) const { return v >= lo && v <= hi; }
};

// Quantise a real value to a signed fixed-point code with `frac` fraction
// bits, round-half-even (how table ROMs are built), saturating to `bits`.
int64_t quantise_real(double v, int frac, int bits);

}  // namespace arp::dp
