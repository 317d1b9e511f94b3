// Cube-face address generator: rotated direction -> face, texel and sub-texel
// position, following the OpenGL cube-map table (faces +X -X +Y -Y +Z -Z):
//
//   face  sc   tc   ma        s = (sc/|ma| + 1) / 2,  t = (tc/|ma| + 1) / 2
//   +X   -rz  -ry   rx        texel position u = s*S, v = t*S (texel row 0 at t = 0)
//   -X   +rz  -ry   rx
//   +Y   +rx  +rz   ry
//   -Y   +rx  -rz   ry
//   +Z   +rx  -ry   rz
//   -Z   -rx  -ry   rz
//
// Tie rule (GL leaves ties to the implementation): X wins over Y and Z, Y over
// Z, when magnitudes are equal -- the rule of Mesa's software cube sampler; a
// major component of exactly zero is positive.
#pragma once
#include <cstdint>
#include <vector>

#include "ArpConfig.hpp"
#include "FixedPoint.hpp"
#include "LensVectorTable.hpp"
#include "ReciprocalUnit.hpp"
#include "common/Units.hpp"

namespace arp::dp {

enum Face : uint8_t { kPosX = 0, kNegX = 1, kPosY = 2, kNegY = 3, kPosZ = 4, kNegZ = 5 };
const char* face_name(int face);

struct CubeAddress {
  uint8_t face;
  int32_t x, y;     // texel holding the sample point (nearest-texel address)
  uint32_t fx, fy;  // position inside that texel, Q0.texel_frac
  int64_t u, v;     // texel-space position s*S, t*S as Q.texel_frac (for bilinear)
};

// The generator's scalar parameters (plain data, cheap to copy into a loop).
struct AddressArith {
  DividerKind divider;
  ReciprocalParams recip;  // recip.lut points into the owning AddressGeneratorParams
  RoundingSel div_rounding, texel_rounding;
  int quot_frac, texel_frac;
  int n_max;  // bit length of the widest |ma|: rot_frac + 1
  int64_t face_size;
  int64_t max_pos;  // S * 2^texel_frac - 1
  // The two fixed shifts with their rounding, worked out once: the reciprocal multiply's
  // (recip_frac + n_max - 1 - quot_frac, div rounding) and the position's (quot_frac + 1 -
  // texel_frac, texel rounding). RoundShift rounds as rshift_round does (FixedPointTest).
  RoundShift quot_shift, texel_shift;
};

// Everything the generator needs, built once from the configuration; owns the reciprocal table.
class AddressGeneratorParams : public AddressArith {
 public:
  AddressGeneratorParams(const DatapathWidths& w, int face_size);
  AddressGeneratorParams(const AddressGeneratorParams& o) : AddressArith(o), table_(o.table_) {
    recip.lut = table_.data();  // the copy owns its own table
  }
  AddressGeneratorParams& operator=(const AddressGeneratorParams&) = delete;

 private:
  std::vector<uint32_t> table_;
};

template <class I>
struct FaceSelectOf {
  uint8_t face;
  I sc, tc, ma;  // ma = |major component|; |sc|, |tc| <= ma
};
using FaceSelect = FaceSelectOf<int64_t>;

// Branch-free (selects only) so a line of pixels vectorises.
// A face's 90 degrees over its S texels: the angle of one texel, priority
// rendering's default threshold angle (theta_t 0 means "one texel").
inline double texel_angle_rad(int face_size) { return (kPi / 2) / face_size; }

// I: int64_t, or int32_t (every component of a Vec3q is an int32_t and |lo| of rot_frac + 2 bits fits).
template <class I>
inline FaceSelectOf<I> select_face_as(const Vec3q& r) {
  const I x = r.x, y = r.y, z = r.z;
  const I ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
  const bool is_x = ax >= ay && ax >= az;
  const bool is_y = !is_x && ay >= az;
  const bool pos = is_x ? x >= 0 : (is_y ? y >= 0 : z >= 0);
  // +X: -z,-y  -X: z,-y  +Y: x,z  -Y: x,-z  +Z: x,-y  -Z: -x,-y
  const I sc = is_x ? (pos ? -z : z) : (is_y ? x : (pos ? x : -x));
  const I tc = is_x ? -y : (is_y ? (pos ? z : -z) : -y);
  const I ma = is_x ? ax : (is_y ? ay : az);
  const int axis = is_x ? 0 : (is_y ? 1 : 2);
  return {static_cast<uint8_t>(2 * axis + (pos ? 0 : 1)), sc, tc, ma};
}
inline FaceSelect select_face(const Vec3q& r) { return select_face_as<int64_t>(r); }

// Face coordinate quotient Q1.quot_frac -> texel-space position Q.texel_frac, clamped to the face.
template <class I>
inline I quotient_to_position_as(I q, const AddressArith& p) {
  const I one = I{1} << p.quot_frac;
  q = q > -one ? q : -one;
  q = q < one ? q : one;
  I pos = p.texel_shift.apply_as<I>((q + one) * static_cast<I>(p.face_size));
  pos = pos > 0 ? pos : 0;
  return pos < static_cast<I>(p.max_pos) ? pos : static_cast<I>(p.max_pos);
}
inline int64_t quotient_to_position(int64_t q, const AddressArith& p) { return quotient_to_position_as<int64_t>(q, p); }

// The reciprocal unit's aligned output for every |ma| (a simulation speed-up:
// the same values, looked up instead of recomputed); empty when the domain is
// too large or the output does not fit 32 bits, or for the exact divider.
std::vector<uint32_t> tabulate_aligned_reciprocal(const AddressGeneratorParams& p, const DatapathWidths& w);

// Whether the generator with the reciprocal table `memo` computes the same in 32-bit lanes
// (select_face_as, multiply_aligned_reciprocal_as, quotient_to_position_as with int32_t): every product,
// rounding and clamp of it fits 32 bits. False without a table.
bool address_fits_int32(const AddressArith& p, const std::vector<uint32_t>& memo);

// `aligned_memo`: optional table from tabulate_aligned_reciprocal (same result).
inline CubeAddress generate_address(const Vec3q& r, const AddressArith& p, const uint32_t* aligned_memo = nullptr) {
  const FaceSelect f = select_face(r);
  int64_t qs = 0, qt = 0;
  if (f.ma > 0) {
    if (p.divider == DividerKind::ReciprocalLut) {
      const int64_t ya = aligned_memo ? int64_t{aligned_memo[f.ma]} : aligned_reciprocal(reciprocal(f.ma, p.recip), p.n_max);
      qs = p.quot_shift.apply(f.sc * ya);  // multiply_aligned_reciprocal, its shift's constants kept
      qt = p.quot_shift.apply(f.tc * ya);
    } else {
      qs = divide_exact(f.sc, f.ma, p.quot_frac, p.div_rounding);
      qt = divide_exact(f.tc, f.ma, p.quot_frac, p.div_rounding);
    }
  }  // a zero vector (only from degenerate widths) addresses the face centre
  const int64_t u = quotient_to_position(qs, p);
  const int64_t v = quotient_to_position(qt, p);
  const int64_t mask = (int64_t{1} << p.texel_frac) - 1;
  return {f.face,
          static_cast<int32_t>(u >> p.texel_frac),
          static_cast<int32_t>(v >> p.texel_frac),
          static_cast<uint32_t>(u & mask),
          static_cast<uint32_t>(v & mask),
          u,
          v};
}

}  // namespace arp::dp
