#include "CubeFaceAddressGenerator.hpp"

namespace arp::dp {

const char* face_name(int face) {
  static const char* names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

AddressGeneratorParams::AddressGeneratorParams(const DatapathWidths& w, int S)
    : AddressArith{w.divider, ReciprocalParams{}, RoundingSel(w.div_rounding), RoundingSel(w.texel_rounding),
                   w.quot_frac, w.texel_frac, w.rot_frac + 1, S, (int64_t{S} << w.texel_frac) - 1},
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

}  // namespace arp::dp
