#include "LinePasses.hpp"

namespace arp::passes {

using namespace arp::dp;

#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define ARP_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "default")))
#else
#define ARP_VECTOR_CLONES
#endif

ARP_VECTOR_CLONES
void rotate_line(const Mat3q& Mref, const int32_t* lx, const int32_t* ly, const int32_t* lz, int x0, int x1,
                 const RotateParams& pref, int32_t* __restrict rx, int32_t* __restrict ry, int32_t* __restrict rz) {
  const Mat3q M = Mref;  // locals: the stores below cannot alias them, so the loop vectorises
  const RotateParams p = pref;
  for (int x = x0; x < x1; ++x) {
    const Vec3q r = rotate(M, Vec3q{lx[x], ly[x], lz[x]}, p);
    rx[x] = r.x;
    ry[x] = r.y;
    rz[x] = r.z;
  }
}

ARP_VECTOR_CLONES
void address_line_lut(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n, const AddressGeneratorParams& pref,
                      const ReciprocalMemo& memo_ref, uint8_t* __restrict face, int64_t* __restrict u,
                      int64_t* __restrict v) {
  const AddressArith p = pref;  // a local copy: the stores cannot alias it
  const int rf = p.recip.recip_frac, qf = p.quot_frac;
  const RoundingSel rs = p.div_rounding;
  const ReciprocalMemo memo = memo_ref;
  if (memo.valid()) {
    for (int i = 0; i < n; ++i) {
      const FaceSelect f = select_face(Vec3q{rx[i], ry[i], rz[i]});
      const int32_t mi = static_cast<int32_t>(f.ma);  // < 2^16: a 32-bit index gathers
      const Reciprocal rc{memo.y[mi], memo.n[mi]};
      const bool zero = f.ma == 0;  // a zero vector addresses the face centre
      const int64_t qs = zero ? 0 : multiply_reciprocal(f.sc, rc, rf, qf, rs);
      const int64_t qt = zero ? 0 : multiply_reciprocal(f.tc, rc, rf, qf, rs);
      face[i] = f.face;
      u[i] = quotient_to_position(qs, p);
      v[i] = quotient_to_position(qt, p);
    }
  } else {
    for (int i = 0; i < n; ++i) {
      const CubeAddress a = generate_address(Vec3q{rx[i], ry[i], rz[i]}, p);
      face[i] = a.face;
      u[i] = a.u;
      v[i] = a.v;
    }
  }
}

void address_line_exact(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n, const AddressGeneratorParams& p,
                        uint8_t* face, int64_t* u, int64_t* v) {
  for (int i = 0; i < n; ++i) {
    const CubeAddress a = generate_address(Vec3q{rx[i], ry[i], rz[i]}, p);
    face[i] = a.face;
    u[i] = a.u;
    v[i] = a.v;
  }
}

ARP_VECTOR_CLONES
void blend_line(const uint32_t* c00, const uint32_t* c10, const uint32_t* c01, const uint32_t* c11, const uint32_t* wx,
                const uint32_t* wy, int n, int texel_frac, const ChannelLayout& L, uint32_t* out) {
  for (int i = 0; i < n; ++i) out[i] = bilinear_blend(c00[i], c10[i], c01[i], c11[i], wx[i], wy[i], texel_frac, L);
}

namespace {

constexpr int TS = DisplayMemoryBank::kTileShift;
constexpr int TM = DisplayMemoryBank::kTile - 1;

// K is the memory count when it is small enough to unroll; K == 0 means "src.count at run time".
template <int K>
void nearest_k(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n, int T,
               const CompositionParams& cp, uint32_t* out) {
  const int count = K > 0 ? K : src.count;
  const int tpr = src.tiles_per_row;
  uint64_t w[16];
  for (int i = 0; i < n; ++i) {
    const int32_t tx = static_cast<int32_t>(u[i] >> T), ty = static_cast<int32_t>(v[i] >> T);
    const size_t ti = static_cast<size_t>((ty >> TS) * tpr + (tx >> TS));
    const int wi = ((ty & TM) << TS) + (tx & TM);
    const auto* const* tabs = src.tables[face[i]];
    for (int k = 0; k < count; ++k) w[k] = tabs[k][ti][wi];
    out[i] = compose(w, count, cp).color;
  }
}

template <int K>
void bilinear_k(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n, int T, int32_t S,
                const CompositionParams& cp, uint32_t* c00, uint32_t* c10, uint32_t* c01, uint32_t* c11, uint32_t* wx,
                uint32_t* wy) {
  const int count = K > 0 ? K : src.count;
  const int tpr = src.tiles_per_row;
  uint64_t w00[16], w10[16], w01[16], w11[16];
  for (int i = 0; i < n; ++i) {
    const BilinearTaps t = bilinear_taps(u[i], v[i], T, S);
    const auto* const* tabs = src.tables[face[i]];
    const size_t t00 = static_cast<size_t>((t.y0 >> TS) * tpr + (t.x0 >> TS));
    const int i00 = ((t.y0 & TM) << TS) + (t.x0 & TM), i10 = ((t.y0 & TM) << TS) + (t.x1 & TM);
    const int i01 = ((t.y1 & TM) << TS) + (t.x0 & TM), i11 = ((t.y1 & TM) << TS) + (t.x1 & TM);
    if ((t.x0 >> TS) == (t.x1 >> TS) && (t.y0 >> TS) == (t.y1 >> TS)) {
      for (int k = 0; k < count; ++k) {  // all four taps in one tile: one tile lookup per memory
        const uint64_t* tile = tabs[k][t00];
        w00[k] = tile[i00]; w10[k] = tile[i10]; w01[k] = tile[i01]; w11[k] = tile[i11];
      }
    } else {
      const size_t t10 = static_cast<size_t>((t.y0 >> TS) * tpr + (t.x1 >> TS));
      const size_t t01 = static_cast<size_t>((t.y1 >> TS) * tpr + (t.x0 >> TS));
      const size_t t11 = static_cast<size_t>((t.y1 >> TS) * tpr + (t.x1 >> TS));
      for (int k = 0; k < count; ++k) {
        w00[k] = tabs[k][t00][i00]; w10[k] = tabs[k][t10][i10]; w01[k] = tabs[k][t01][i01]; w11[k] = tabs[k][t11][i11];
      }
    }
    c00[i] = compose(w00, count, cp).color;
    c10[i] = compose(w10, count, cp).color;
    c01[i] = compose(w01, count, cp).color;
    c11[i] = compose(w11, count, cp).color;
    wx[i] = t.wx;
    wy[i] = t.wy;
  }
}

}  // namespace

void compose_nearest_line(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n, int T,
                          const CompositionParams& cp, uint32_t* out) {
  switch (src.count) {
    case 0: for (int i = 0; i < n; ++i) out[i] = cp.background; break;
    case 1: nearest_k<1>(src, face, u, v, n, T, cp, out); break;
    case 2: nearest_k<2>(src, face, u, v, n, T, cp, out); break;
    case 3: nearest_k<3>(src, face, u, v, n, T, cp, out); break;
    case 4: nearest_k<4>(src, face, u, v, n, T, cp, out); break;
    default: nearest_k<0>(src, face, u, v, n, T, cp, out); break;
  }
}

void compose_bilinear_line(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n, int T,
                           int32_t S, const CompositionParams& cp, uint32_t* c00, uint32_t* c10, uint32_t* c01,
                           uint32_t* c11, uint32_t* wx, uint32_t* wy) {
  switch (src.count) {
    case 0:
      for (int i = 0; i < n; ++i) {
        const BilinearTaps t = bilinear_taps(u[i], v[i], T, S);
        c00[i] = c10[i] = c01[i] = c11[i] = cp.background;
        wx[i] = t.wx;
        wy[i] = t.wy;
      }
      break;
    case 1: bilinear_k<1>(src, face, u, v, n, T, S, cp, c00, c10, c01, c11, wx, wy); break;
    case 2: bilinear_k<2>(src, face, u, v, n, T, S, cp, c00, c10, c01, c11, wx, wy); break;
    case 3: bilinear_k<3>(src, face, u, v, n, T, S, cp, c00, c10, c01, c11, wx, wy); break;
    case 4: bilinear_k<4>(src, face, u, v, n, T, S, cp, c00, c10, c01, c11, wx, wy); break;
    default: bilinear_k<0>(src, face, u, v, n, T, S, cp, c00, c10, c01, c11, wx, wy); break;
  }
}

}  // namespace arp::passes
