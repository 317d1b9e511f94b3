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

}  // namespace arp::dp
