#include "CubeFaceAddressGenerator.hpp"

#include <algorithm>
#include <climits>

namespace arp::dp {

const char* face_name(int face) {
  static const char* names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

AddressGeneratorParams::AddressGeneratorParams(const DatapathWidths& w, int S)
    : AddressArith{w.divider, ReciprocalParams{}, RoundingSel(w.div_rounding), RoundingSel(w.texel_rounding),
                   w.quot_frac, w.texel_frac, w.rot_frac + 1, S, (int64_t{S} << w.texel_frac) - 1,
                   RoundShift(w.recip_frac_bits + (w.rot_frac + 1) - 1 - w.quot_frac, w.div_rounding),
                   RoundShift(w.quot_frac + 1 - w.texel_frac, w.texel_rounding)},
      table_(build_reciprocal_table(w.recip_index_bits, w.recip_frac_bits)) {
  recip.lut = table_.data();
  recip.index_bits = w.recip_index_bits;
  recip.recip_frac = w.recip_frac_bits;
  recip.newton_steps = w.newton_steps;
  recip.rounding = div_rounding;
}

std::vector<uint32_t> tabulate_aligned_reciprocal(const AddressGeneratorParams& p, const DatapathWidths& w) {
  std::vector<uint32_t> memo;
  // |ma| < 2^(rot_frac+1); the aligned output y' < 2^(recip_frac + 1 + n_max - 1) must fit 32 bits.
  if (w.divider != DividerKind::ReciprocalLut || w.rot_frac > 15 || w.recip_frac_bits + w.rot_frac + 1 > 31) return memo;
  const size_t domain = size_t{1} << (w.rot_frac + 1);
  memo.resize(domain);
  for (size_t m = 0; m < domain; ++m)
    memo[m] = static_cast<uint32_t>(aligned_reciprocal(reciprocal(static_cast<int64_t>(m), p.recip), p.n_max));
  return memo;
}

bool address_fits_int32(const AddressArith& p, const std::vector<uint32_t>& memo) {
  constexpr int64_t kMax = INT32_MAX;
  if (memo.empty() || p.n_max > 30) return false;  // select_face negates components of rot_frac + 2 bits
  // The reciprocal multiply: |sc| <= ma, so |sc * y'| <= ma * memo[ma]; shifted as rshift_round does.
  const int64_t s = int64_t{p.recip.recip_frac} + p.n_max - 1 - p.quot_frac;
  const int64_t left = s < 0 ? -s : 0, half = s > 0 ? int64_t{1} << (s - 1) : 0;
  if (left > 30) return false;
  int64_t product = 0;
  for (size_t m = 1; m < memo.size(); ++m) {
    if (memo[m] > kMax) return false;
    product = std::max(product, static_cast<int64_t>(m) * memo[m]);
  }
  if (product > ((kMax - half - 1) >> left)) return false;
  // The position: (q + one) * S with q clamped to +-one, shifted by quot_frac + 1 - texel_frac.
  const int64_t s2 = int64_t{p.quot_frac} + 1 - p.texel_frac;
  const int64_t left2 = s2 < 0 ? -s2 : 0, half2 = s2 > 0 ? int64_t{1} << (s2 - 1) : 0;
  if (p.quot_frac > 29 || left2 > 30 || p.face_size > kMax || p.max_pos > kMax) return false;
  const int64_t span = (int64_t{2} << p.quot_frac);
  if (span > kMax / p.face_size) return false;
  return span * p.face_size <= ((kMax - half2 - 1) >> left2);
}

}  // namespace arp::dp
