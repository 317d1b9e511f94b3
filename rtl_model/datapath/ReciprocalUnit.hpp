// Division by the major-axis component: either a reciprocal unit (leading-one
// normaliser, lookup table indexed by the top mantissa bits, optional
// Newton-Raphson steps, one multiply per quotient) or an exact divider.
#pragma once
#include <cstdint>
#include <type_traits>
#include <vector>

#include "ArpConfig.hpp"
#include "FixedPoint.hpp"

namespace arp::dp {

// v >> s with the given rounding (s may be <= 0: exact left shift), branch-free.
// half_sel is 1 for the round-to-nearest modes, even is 1 for HalfEven.
// I: the type the shift is computed in; int64_t holds every valid width. A narrower I gives the same
// result where the caller has proven that v << max(-s, 0) plus half fits it (address_fits_int32).
template <class I>
inline I rshift_round_as(I v, I s, I half_sel, I even) {
  const I left = s < 0 ? -s : 0, right = s > 0 ? s : 0;
  const I w = static_cast<I>(static_cast<std::make_unsigned_t<I>>(v) << left);
  const I on = right > 0 ? 1 : 0;  // no fraction bits dropped: nothing to round
  const I ev = even & on;
  const I half = on * (I{1} << (right - on));  // 2^(right-1), written so GCC vectorises it
  return (w + half_sel * (half - ev) + ((w >> right) & ev)) >> right;
}
inline int64_t rshift_round(int64_t v, int64_t s, int64_t half_sel, int64_t even) {
  return rshift_round_as<int64_t>(v, s, half_sel, even);
}

struct RoundingSel {
  int64_t half_sel = 0, even = 0;
  RoundingSel() = default;
  explicit RoundingSel(Rounding r)
      : half_sel(r == Rounding::Floor ? 0 : 1), even(r == Rounding::HalfEven ? 1 : 0) {}
};

// Table of 1/M for M in [1, 2): entry i covers M in [1 + i/2^k, 1 + (i+1)/2^k)
// and holds the midpoint of the reciprocal's range over it (minimises the
// largest relative error), as an unsigned Q1.recip_frac code.
std::vector<uint32_t> build_reciprocal_table(int index_bits, int recip_frac);

struct ReciprocalParams {
  const uint32_t* lut = nullptr;
  int index_bits = 8;
  int recip_frac = 16;
  int newton_steps = 1;
  RoundingSel rounding;
};

// 1/m for an unsigned m > 0, returned as mantissa y (Q1.recip_frac, 1/M for
// M = m / 2^(n-1)) and the bit length n of m, so that 1/m = y * 2^(1-n-recip_frac).
struct Reciprocal {
  int64_t y;
  int n;
};

inline Reciprocal reciprocal(int64_t m_in, const ReciprocalParams& p) {
  // m == 0 has no reciprocal; callers never use its result (a zero vector
  // addresses the face centre) but the arithmetic stays defined: 1/1.
  const int64_t m = m_in > 0 ? m_in : 1;
  const int n = 64 - __builtin_clzll(static_cast<uint64_t>(m));
  const int64_t frac_part = m - (int64_t{1} << (n - 1));
  const int below = n - 1 - p.index_bits;
  const int64_t idx = below >= 0 ? (frac_part >> below) : (frac_part << (-below));
  int64_t y = p.lut[idx];
  for (int k = 0; k < p.newton_steps; ++k) {
    // y <- y * (2 - M*y); M*y first reduced to Q.recip_frac.
    const int64_t my = rshift_round(m * y, n - 1, p.rounding.half_sel, p.rounding.even);
    const int64_t t = (int64_t{2} << p.recip_frac) - my;
    y = rshift_round(y * t, p.recip_frac, p.rounding.half_sel, p.rounding.even);
  }
  return {y, n};
}

// sc / m as signed Q1.quot_frac using the reciprocal: one multiply and a
// shift that depends on m's leading-one position n.
inline int64_t multiply_reciprocal(int64_t sc, const Reciprocal& r, int recip_frac, int quot_frac,
                                   const RoundingSel& rs) {
  return rshift_round(sc * r.y, recip_frac + r.n - 1 - quot_frac, rs.half_sel, rs.even);
}

// The reciprocal unit's output stage: the normalised reciprocal shifted back
// by the leading-one position (a denormalising shifter), so it has a fixed
// binary point: y' = y * 2^(n_max - n), n_max = rot_frac + 1 (the widest |ma|).
inline int64_t aligned_reciprocal(const Reciprocal& r, int n_max) {
  return static_cast<int64_t>(static_cast<uint64_t>(r.y) << (n_max - r.n));
}

// sc / m from the aligned reciprocal: one multiply and a fixed shift. Equal to
// multiply_reciprocal bit for bit: rounding v * 2^k at a shift k larger
// rounds v identically in every mode (floor, half up, and half even, whose
// tie bit moves with the value), and |sc| <= m keeps sc * y' below 2^61.
// In a type I where sc * aligned and the rounding fit (see rshift_round_as).
template <class I>
inline I multiply_aligned_reciprocal_as(I sc, I aligned, int recip_frac, int n_max, int quot_frac, const RoundingSel& rs) {
  return rshift_round_as<I>(sc * aligned, static_cast<I>(recip_frac + n_max - 1 - quot_frac), static_cast<I>(rs.half_sel),
                            static_cast<I>(rs.even));
}
inline int64_t multiply_aligned_reciprocal(int64_t sc, int64_t aligned, int recip_frac, int n_max, int quot_frac,
                                           const RoundingSel& rs) {
  return multiply_aligned_reciprocal_as<int64_t>(sc, aligned, recip_frac, n_max, quot_frac, rs);
}

// sc / m as signed Q1.quot_frac by exact integer division with the rounding mode.
inline int64_t divide_exact(int64_t sc, int64_t m, int quot_frac, const RoundingSel& rs) {
  const int64_t num = static_cast<int64_t>(static_cast<uint64_t>(sc) << quot_frac);
  int64_t q = num / m;
  int64_t r = num % m;
  if (r < 0) { --q; r += m; }  // floor division (m > 0)
  const int64_t twice = 2 * r;
  const int64_t up = rs.half_sel * ((twice > m) | ((twice == m) & (1 - rs.even)) | ((twice == m) & rs.even & (q & 1)));
  return q + up;
}

}  // namespace arp::dp
