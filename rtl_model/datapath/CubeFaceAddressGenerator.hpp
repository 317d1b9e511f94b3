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
#include "LensVectorTable.hpp"
#include "ReciprocalUnit.hpp"

namespace arp::dp {

enum Face : uint8_t { kPosX = 0, kNegX = 1, kPosY = 2, kNegY = 3, kPosZ = 4, kNegZ = 5 };
const char* face_name(int face);

struct CubeAddress {
  uint8_t face;
  int32_t x, y;     // texel holding the sample point (nearest-texel address)
  uint32_t fx, fy;  // position inside that texel, Q0.texel_frac
  int64_t u, v;     // texel-space position s*S, t*S as Q.texel_frac (for bilinear)
};

// Everything the generator needs, built once from the configuration.
class AddressGeneratorParams {
 public:
  AddressGeneratorParams(const DatapathWidths& w, int face_size);
  AddressGeneratorParams(const AddressGeneratorParams& o) : AddressGeneratorParams(o, 0) {}
  AddressGeneratorParams& operator=(const AddressGeneratorParams&) = delete;
  DividerKind divider;
  ReciprocalParams recip;
  RoundingSel div_rounding, texel_rounding;
  int quot_frac, texel_frac;
  int64_t face_size;
  int64_t max_pos;  // S * 2^texel_frac - 1

 private:
  AddressGeneratorParams(const AddressGeneratorParams& o, int)
      : divider(o.divider), recip(o.recip), div_rounding(o.div_rounding), texel_rounding(o.texel_rounding),
        quot_frac(o.quot_frac), texel_frac(o.texel_frac), face_size(o.face_size), max_pos(o.max_pos),
        table_(o.table_) {
    recip.lut = table_.data();  // the copy owns its own table
  }
  std::vector<uint32_t> table_;
};

struct FaceSelect {
  uint8_t face;
  int64_t sc, tc, ma;  // ma = |major component|
};

inline FaceSelect select_face(const Vec3q& r) {
  const int64_t ax = r.x < 0 ? -int64_t{r.x} : r.x;
  const int64_t ay = r.y < 0 ? -int64_t{r.y} : r.y;
  const int64_t az = r.z < 0 ? -int64_t{r.z} : r.z;
  if (ax >= ay && ax >= az) {
    return r.x >= 0 ? FaceSelect{kPosX, -int64_t{r.z}, -int64_t{r.y}, ax}
                    : FaceSelect{kNegX, int64_t{r.z}, -int64_t{r.y}, ax};
  }
  if (ay >= az) {
    return r.y >= 0 ? FaceSelect{kPosY, int64_t{r.x}, int64_t{r.z}, ay}
                    : FaceSelect{kNegY, int64_t{r.x}, -int64_t{r.z}, ay};
  }
  return r.z >= 0 ? FaceSelect{kPosZ, int64_t{r.x}, -int64_t{r.y}, az}
                  : FaceSelect{kNegZ, -int64_t{r.x}, -int64_t{r.y}, az};
}

// Face coordinate quotient Q1.quot_frac -> texel-space position Q.texel_frac, clamped to the face.
inline int64_t quotient_to_position(int64_t q, const AddressGeneratorParams& p) {
  const int64_t one = int64_t{1} << p.quot_frac;
  q = q < -one ? -one : (q > one ? one : q);
  int64_t pos = rshift_round((q + one) * p.face_size, p.quot_frac + 1 - p.texel_frac, p.texel_rounding.half_sel,
                             p.texel_rounding.even);
  return pos < 0 ? 0 : (pos > p.max_pos ? p.max_pos : pos);
}

inline CubeAddress generate_address(const Vec3q& r, const AddressGeneratorParams& p) {
  const FaceSelect f = select_face(r);
  int64_t qs = 0, qt = 0;
  if (f.ma > 0) {
    if (p.divider == DividerKind::ReciprocalLut) {
      const Reciprocal rc = reciprocal(f.ma, p.recip);
      qs = multiply_reciprocal(f.sc, rc, p.recip.recip_frac, p.quot_frac, p.div_rounding);
      qt = multiply_reciprocal(f.tc, rc, p.recip.recip_frac, p.quot_frac, p.div_rounding);
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
