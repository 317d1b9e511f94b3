// Fixed-point primitives shared by every datapath stage. Widths and rounding
// are run-time values so a width sweep needs no rebuild; every function is
// branch-free so the functional model's loops can vectorise.
#pragma once
#include <cstdint>
#include <string>
#include <type_traits>

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
  constexpr int64_t apply(int64_t v) const { return apply_as<int64_t>(v); }
  // The same shift in a narrower type I, for loops that hold more lanes of it: the caller has proven that
  // v << left plus the bias fits I (e.g. rotate_fits_int32), so every result is apply's.
  template <class I>
  constexpr I apply_as(I v) const {
    const I w = static_cast<I>(static_cast<std::make_unsigned_t<I>>(v) << left);
    return (w + static_cast<I>(bias) + ((w >> right) & static_cast<I>(even))) >> right;
  }
};

// Saturation to a signed two's-complement width (bits includes the sign).
struct SignedRange {
  int64_t lo = 0, hi = 0;
  SignedRange() = default;
  explicit SignedRange(int bits)
      : lo(-(int64_t{1} << (bits - 1))), hi((int64_t{1} << (bits - 1)) - 1) {}
  constexpr int64_t clamp(int64_t v) const { return clamp_as<int64_t>(v); }
  // In a narrower type I holding lo and hi (a narrow loop's; see RoundShift::apply_as).
  template <class I>
  constexpr I clamp_as(I v) const {
    const I a = v > static_cast<I>(lo) ? v : static_cast<I>(lo);  // written as max then min so loops vectorise
    return a < static_cast<I>(hi) ? a : static_cast<I>(hi);
  }
  constexpr bool contains(int64_t v) const { return v >= lo && v <= hi; }
};

// Quantise a real value to a signed fixed-point code with `frac` fraction
// bits, round-half-even (how table ROMs are built), saturating to `bits`.
int64_t quantise_real(double v, int frac, int bits);

}  // namespace arp::dp
