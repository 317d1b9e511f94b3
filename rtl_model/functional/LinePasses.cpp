#include "LinePasses.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "common/VectorClones.hpp"

namespace arp::passes {

using namespace arp::dp;


namespace {
constexpr int TS = DisplayMemoryBank::kTileShift;
constexpr int TM = DisplayMemoryBank::kTile - 1;
constexpr int TR = DisplayMemoryBank::kTileStride;  // words a stored tile row (texels + apron)

// The tile of texel (x, y) of `face` in the flattened six-face table (EyeSources), and its word in the tile.
[[gnu::always_inline]] inline int32_t tile_of(int32_t face, int32_t x, int32_t y, int tpr, int tpf) {
  return face * tpf + (y >> TS) * tpr + (x >> TS);
}
[[gnu::always_inline]] inline int32_t word_of(int32_t x, int32_t y) { return (y & TM) * TR + (x & TM); }
}  // namespace

namespace {
// I: the lanes' integer type, int32_t where the configuration's bounds fit it (twice the lanes of int64_t).
template <class I>
[[gnu::always_inline]] inline void rotate_impl(const Mat3q& Mref, const int32_t* lx, const int32_t* ly, const int32_t* lz,
                                               int x0, int x1, const RotateParams& pref, int32_t* __restrict rx,
                                               int32_t* __restrict ry, int32_t* __restrict rz) {
  const Mat3q M = Mref;  // locals: the stores below cannot alias them, so the loop vectorises
  const RotateParams p = pref;
  for (int x = x0; x < x1; ++x) {
    const Vec3q r = rotate_as<I>(M, Vec3q{lx[x], ly[x], lz[x]}, p);
    rx[x] = r.x;
    ry[x] = r.y;
    rz[x] = r.z;
  }
}
}  // namespace

ARP_VECTOR_CLONES
void rotate_line(const Mat3q& M, const int32_t* lx, const int32_t* ly, const int32_t* lz, int x0, int x1,
                 const RotateParams& p, bool int32_lanes, int32_t* rx, int32_t* ry, int32_t* rz) {
  if (int32_lanes) rotate_impl<int32_t>(M, lx, ly, lz, x0, x1, p, rx, ry, rz);
  else rotate_impl<int64_t>(M, lx, ly, lz, x0, x1, p, rx, ry, rz);
}

namespace {
template <class I>
[[gnu::always_inline]] inline void address_lut_impl(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n,
                                                    const AddressArith& pref, const uint32_t* aligned,
                                                    int32_t* __restrict face, int32_t* __restrict u,
                                                    int32_t* __restrict v) {
  const AddressArith p = pref;  // a local copy: the stores cannot alias it
  for (int i = 0; i < n; ++i) {
    const FaceSelectOf<I> f = select_face_as<I>(Vec3q{rx[i], ry[i], rz[i]});
    const I ya = static_cast<I>(aligned[static_cast<int32_t>(f.ma)]);  // ma < 2^16: a 32-bit index gathers
    const bool zero = f.ma == 0;  // a zero vector addresses the face centre
    const I qs = zero ? 0 : p.quot_shift.apply_as<I>(f.sc * ya);  // as generate_address
    const I qt = zero ? 0 : p.quot_shift.apply_as<I>(f.tc * ya);
    face[i] = f.face;
    u[i] = static_cast<int32_t>(quotient_to_position_as<I>(qs, p));
    v[i] = static_cast<int32_t>(quotient_to_position_as<I>(qt, p));
  }
}
}  // namespace

ARP_VECTOR_CLONES
void address_line_lut(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n, const AddressGeneratorParams& p,
                      const ReciprocalMemo& memo, int32_t* __restrict face, int32_t* __restrict u,
                      int32_t* __restrict v) {
  if (memo.valid()) {
    if (memo.int32_lanes) address_lut_impl<int32_t>(rx, ry, rz, n, p, memo.aligned, face, u, v);
    else address_lut_impl<int64_t>(rx, ry, rz, n, p, memo.aligned, face, u, v);
  } else {
    for (int i = 0; i < n; ++i) {
      const CubeAddress a = generate_address(Vec3q{rx[i], ry[i], rz[i]}, p);
      face[i] = a.face;
      u[i] = static_cast<int32_t>(a.u);
      v[i] = static_cast<int32_t>(a.v);
    }
  }
}

void address_line_exact(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n, const AddressGeneratorParams& p,
                        int32_t* face, int32_t* u, int32_t* v) {
  for (int i = 0; i < n; ++i) {
    const CubeAddress a = generate_address(Vec3q{rx[i], ry[i], rz[i]}, p);
    face[i] = a.face;
    u[i] = static_cast<int32_t>(a.u);
    v[i] = static_cast<int32_t>(a.v);
  }
}

namespace {
ARP_VECTOR_CLONES
void nearest_refs_impl(const int32_t* __restrict face, const int32_t* __restrict u, const int32_t* __restrict v, int n,
                       int T, int tpr, int tpf, int32_t* __restrict tile, int32_t* __restrict word) {
  for (int i = 0; i < n; ++i) {
    const int32_t tx = u[i] >> T, ty = v[i] >> T;  // the nearest texel: CubeAddress::x, y
    tile[i] = tile_of(face[i], tx, ty, tpr, tpf);
    word[i] = word_of(tx, ty);
  }
}
}  // namespace

void nearest_refs_line(const int32_t* face, const int32_t* u, const int32_t* v, int n, int T, const EyeSources& src,
                       TexelRef out) {
  nearest_refs_impl(face, u, v, n, T, src.tiles_per_row, src.tiles_per_face, out.tile, out.word);
}

namespace {
inline uint64_t texel(const uint64_t* pool, const int32_t* offset, int32_t tile, int32_t word) {
  return pool[static_cast<int64_t>(offset[tile]) + word];
}

}  // namespace

namespace {
// How many pixels ahead the multi-memory loops ask for their texels: the loads are latency bound (the
// memories' texels of a strip span several times the caches' reach), and the core alone does not look
// that far ahead (nearest, one thread, four full memories, composed in the loop as it then was: 63-66
// M px/s without, 89-97 with 16, 32 or 64 ahead, 32 the best; 115-117 with a block's first 32 asked for
// at its start and the memories' pointers held in locals; arp_bench_functional, runs alternating,
// 2026-11-26). Once the loads no longer read the tile tables (EyeSources::dense) the loop ran ahead of
// 32: nearest, four memories, 3.74-4.06 ms a frame at 32, 3.18-3.41 at 64, 96 and 128 with the look-ahead
// running across blocks (bilinear the same within noise at each).
constexpr int kAhead = 96;

// Pixels per block of the passes that keep per-pixel arrays (they stay within L1).
constexpr int kBlock = 128;

// Several memories: the texel loads alone in a scalar loop, into per-memory arrays, then the
// composition (and the bilinear blend) in vectors. Faster than composing in the scalar loop (bilinear,
// one thread: two memories 104-112 -> 124-137 M px/s, four 71-74 -> 82-86; bench/FunctionalModelBench,
// alternating, 2026-11-26). K: the memory count, fixed up to the composition unit's eight inputs so the
// composition unrolls into selects; K == 0: more, up to 16, counted at run time, in smaller blocks. (Until
// 2026-11-26 five to eight memories were counted at run time, in blocks of 32 pixels, which left the
// prefetch no pixels ahead within a block: bilinear, one thread, eight memories 12.7 M px/s.)
template <int K>
struct Block {
  static constexpr int kMemories = K > 0 ? K : 16;
  // The words of a block stay within L1: 4 taps x 8 bytes x K x pixels.
  static constexpr int kPixels = K == 0 ? 32 : K <= 4 ? kBlock : kBlock / 2;
};

// The memories' pools and tile tables as locals: the loops' stores cannot alias them. Dense: every
// memory's tiles lie in the pool in table order (EyeSources::dense), so a texel's place is arithmetic
// and the same for every memory -- no tile table read per memory.
template <int K, bool Dense>
struct Pools {
  const uint64_t* pool[Block<K>::kMemories];
  const int32_t* offset[Block<K>::kMemories];
  int count;
  explicit Pools(const EyeSources& src) : count(K > 0 ? K : src.count) {
    for (int k = 0; k < count; ++k) {
      pool[k] = Dense ? src.dense_base[k] : src.pool[k];
      offset[k] = src.offset[k];
    }
  }
  const uint64_t* at(int k, int32_t tile, int32_t word) const {
    if constexpr (Dense) return pool[k] + static_cast<int64_t>(tile) * DisplayMemoryBank::kTileWords + word;
    else return pool[k] + static_cast<int64_t>(offset[k][tile]) + word;
  }
};

// Pixels [i0, i0 + n) of a line of `line` pixels whose texel places are all known: the prefetch looks
// ahead across the block's end, into the next block's pixels; a line's first pixels are asked for at once.
template <int K, bool Dense>
void nearest_load(const Pools<K, Dense>& p, const int32_t* __restrict tile, const int32_t* __restrict word, int i0,
                  int n, int line, uint64_t (*__restrict w)[Block<K>::kPixels]) {
  if (i0 == 0)
    for (int i = 0; i < std::min(line, kAhead); ++i)
      for (int k = 0; k < p.count; ++k) __builtin_prefetch(p.at(k, tile[i], word[i]));
  for (int i = 0; i < n; ++i) {
    const int j = i0 + i;
    if (j + kAhead < line)
      for (int k = 0; k < p.count; ++k) __builtin_prefetch(p.at(k, tile[j + kAhead], word[j + kAhead]));
    for (int k = 0; k < p.count; ++k) w[k][i] = *p.at(k, tile[j], word[j]);
  }
}

template <int K>
[[gnu::always_inline]] inline void compose_nearest_body(const uint64_t (*__restrict w)[Block<K>::kPixels], int count_rt,
                                                        int n, const CompositionParams& cpref,
                                                        uint32_t* __restrict out) {
  const int count = K > 0 ? K : count_rt;  // a constant the loops unroll by
  const CompositionParams cp = cpref;
  for (int i = 0; i < n; ++i) {
    uint64_t x[Block<K>::kMemories] = {};  // (K == 0: the compiler cannot see count >= 1)
#pragma GCC unroll 8
    for (int k = 0; k < count; ++k) x[k] = w[k][i];
    out[i] = compose(x, count, cp).color;
  }
}

#define ARP_COMPOSE_NEAREST(K)                                                                                 \
  ARP_VECTOR_CLONES void compose_nearest_##K(const uint64_t (*w)[Block<K>::kPixels], int count, int n,        \
                                             const CompositionParams& cp, uint32_t* out) {                    \
    compose_nearest_body<K>(w, count, n, cp, out);                                                            \
  }
ARP_COMPOSE_NEAREST(2)
ARP_COMPOSE_NEAREST(3)
ARP_COMPOSE_NEAREST(4)
ARP_COMPOSE_NEAREST(5)
ARP_COMPOSE_NEAREST(6)
ARP_COMPOSE_NEAREST(7)
ARP_COMPOSE_NEAREST(8)
#undef ARP_COMPOSE_NEAREST
void compose_nearest_0(const uint64_t (*w)[Block<0>::kPixels], int count, int n, const CompositionParams& cp,
                       uint32_t* out) {
  compose_nearest_body<0>(w, count, n, cp, out);
}

template <int K, bool Dense>
void nearest_memories_impl(const EyeSources& src, TexelRef ref, int n, const CompositionParams& cp, uint32_t* out) {
  constexpr int B = Block<K>::kPixels;
  const Pools<K, Dense> p(src);
  alignas(64) uint64_t w[Block<K>::kMemories][B];
  for (int i0 = 0; i0 < n; i0 += B) {
    const int m = std::min(B, n - i0);
    nearest_load<K, Dense>(p, ref.tile, ref.word, i0, m, n, w);
    if constexpr (K == 2) compose_nearest_2(w, p.count, m, cp, out + i0);
    else if constexpr (K == 3) compose_nearest_3(w, p.count, m, cp, out + i0);
    else if constexpr (K == 4) compose_nearest_4(w, p.count, m, cp, out + i0);
    else if constexpr (K == 5) compose_nearest_5(w, p.count, m, cp, out + i0);
    else if constexpr (K == 6) compose_nearest_6(w, p.count, m, cp, out + i0);
    else if constexpr (K == 7) compose_nearest_7(w, p.count, m, cp, out + i0);
    else if constexpr (K == 8) compose_nearest_8(w, p.count, m, cp, out + i0);
    else compose_nearest_0(w, p.count, m, cp, out + i0);
  }
}
template <int K>
void nearest_memories(const EyeSources& src, TexelRef ref, int n, const CompositionParams& cp, uint32_t* out) {
  if (src.dense) nearest_memories_impl<K, true>(src, ref, n, cp, out);
  else nearest_memories_impl<K, false>(src, ref, n, cp, out);
}
}  // namespace

void fetch_compose_line(const EyeSources& src, TexelRef ref, int n, const CompositionParams& cp, uint32_t* out) {
  switch (src.count) {
    case 0: for (int i = 0; i < n; ++i) out[i] = cp.background; break;
    case 2: nearest_memories<2>(src, ref, n, cp, out); break;
    case 3: nearest_memories<3>(src, ref, n, cp, out); break;
    case 4: nearest_memories<4>(src, ref, n, cp, out); break;
    case 5: nearest_memories<5>(src, ref, n, cp, out); break;
    case 6: nearest_memories<6>(src, ref, n, cp, out); break;
    case 7: nearest_memories<7>(src, ref, n, cp, out); break;
    case 8: nearest_memories<8>(src, ref, n, cp, out); break;
    default: nearest_memories<0>(src, ref, n, cp, out); break;  // one memory too (its fused pass is faster)
  }
}

namespace {
// The single-memory bilinear path in three passes over a block of pixels: tap positions (vectors),
// the texel loads (a scalar loop on purpose), composition and blend (vectors). One fused vector loop
// was slower: a gather of eight 64-bit words costs about as much as eight plain loads on Zen 4 and
// stalls the loop around it, while plain loads overlap (bench/FunctionalModelBench: 117-125 against
// 139-162 M px/s on one thread, runs alternating, 2026-11-26).

ARP_VECTOR_CLONES
void bilinear_taps_impl(const int32_t* __restrict face, const int32_t* __restrict u, const int32_t* __restrict v, int n,
                        int T, int32_t S, int tpr, int tpf, int32_t* __restrict tile, int32_t* __restrict w0,
                        int32_t* __restrict dy, uint32_t* __restrict wx, uint32_t* __restrict wy) {
  for (int i = 0; i < n; ++i) {
    const BilinearTaps t = bilinear_taps_as<int32_t>(u[i], v[i], T, S);  // u, v are 32-bit: so is every step
    // All four taps lie in the tile of (x0, y0): x1 - x0 and y1 - y0 are 0 or
    // 1, and a stored tile's apron holds its right and bottom neighbours' edges.
    tile[i] = tile_of(face[i], t.x0, t.y0, tpr, tpf);
    w0[i] = word_of(t.x0, t.y0);
    dy[i] = (t.y1 - t.y0) * TR;
    // At a face's first or last column both horizontal taps are the same texel (x1 == x0). The loads then
    // take the pair's right-hand word from the apron, and the weight of x1 is made 0: per channel
    // c00 (W - 0) + c10' 0 = c00 W = c00 (W - wx) + c00 wx, the blend of the same texel twice, exactly.
    wx[i] = t.x1 != t.x0 ? t.wx : 0;
    wy[i] = t.wy;
  }
}

// No vector clone: the baseline has no gathers, so the loads stay scalar. Each row of a quad is one
// 16-byte pair, as in bilinear_load below: row0[2 i + column], row1[2 i + column]. Dense: the memory's
// tiles lie in its pool in table order (EyeSources::dense), so a quad's place is arithmetic, without the
// tile table's dependent load.
template <bool Dense>
void bilinear_load_impl(const uint64_t* __restrict pool, const int32_t* __restrict offset,
                        const int32_t* __restrict tile, const int32_t* __restrict w0, const int32_t* __restrict dy,
                        int n, uint64_t* __restrict row0, uint64_t* __restrict row1) {
  for (int i = 0; i < n; ++i) {
    const int64_t at = Dense ? int64_t{tile[i]} * DisplayMemoryBank::kTileWords : int64_t{offset[tile[i]]};
    const uint64_t* q = pool + at + w0[i];
    std::memcpy(row0 + 2 * i, q, 16);
    std::memcpy(row1 + 2 * i, q + dy[i], 16);
  }
}

// Acc: the blend's accumulator (uint32_t where dp::blend_fits_32: the same value, twice the lanes).
template <class Acc>
[[gnu::always_inline]] inline void bilinear_blend_body(const uint64_t* __restrict row0, const uint64_t* __restrict row1,
                                                       const uint32_t* __restrict wx, const uint32_t* __restrict wy,
                                                       int n, int T, const ChannelLayout& Lref,
                                                       const CompositionParams& cpref, uint32_t* __restrict out) {
  const ChannelLayout L = Lref;
  const CompositionParams cp = cpref;
  for (int i = 0; i < n; ++i)
    out[i] = bilinear_blend_in<Acc>(compose(&row0[2 * i], 1, cp).color, compose(&row0[2 * i + 1], 1, cp).color,
                                    compose(&row1[2 * i], 1, cp).color, compose(&row1[2 * i + 1], 1, cp).color, wx[i],
                                    wy[i], T, L);
}

ARP_VECTOR_CLONES
void bilinear_blend_32(const uint64_t* row0, const uint64_t* row1, const uint32_t* wx, const uint32_t* wy, int n, int T,
                       const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  bilinear_blend_body<uint32_t>(row0, row1, wx, wy, n, T, L, cp, out);
}

ARP_VECTOR_CLONES
void bilinear_blend_64(const uint64_t* row0, const uint64_t* row1, const uint32_t* wx, const uint32_t* wy, int n, int T,
                       const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  bilinear_blend_body<uint64_t>(row0, row1, wx, wy, n, T, L, cp, out);
}

void bilinear_single_impl(const uint64_t* pool, const int32_t* offset, bool dense, const int32_t* face,
                          const int32_t* u, const int32_t* v, int n, int T, int32_t S, int tpr, int tpf,
                          const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  alignas(64) int32_t tile[kBlock], w0[kBlock], dy[kBlock];
  alignas(64) uint32_t wx[kBlock], wy[kBlock];
  alignas(64) uint64_t row0[2 * kBlock], row1[2 * kBlock];
  const auto blend = blend_fits_32(T, L) ? bilinear_blend_32 : bilinear_blend_64;
  for (int i0 = 0; i0 < n; i0 += kBlock) {
    const int m = std::min(kBlock, n - i0);
    bilinear_taps_impl(face + i0, u + i0, v + i0, m, T, S, tpr, tpf, tile, w0, dy, wx, wy);
    if (dense) bilinear_load_impl<true>(pool, offset, tile, w0, dy, m, row0, row1);
    else bilinear_load_impl<false>(pool, offset, tile, w0, dy, m, row0, row1);
    blend(row0, row1, wx, wy, m, T, L, cp, out + i0);
  }
}

// Bilinear over several memories likewise: per pixel and memory one tile lookup for the four taps (the
// apron), their words into per-memory arrays; then each tap's composition and the blend in vectors.
// Pixels [i0, i0 + n) of a line of `line` pixels whose taps are all known: as nearest_load, the prefetch
// (both rows of a quad) looks ahead across the block's end. Each row of a quad is its two neighbouring
// words, read and stored as one 16-byte pair (the apron keeps the right-hand word within the stored tile,
// and below it the apron row): w[k][row][2 i + column]. At a face's first or last column the right-hand word
// is the apron's, weighted 0 (bilinear_taps_impl).
template <int K, bool Dense>
void bilinear_load(const Pools<K, Dense>& p, const int32_t* __restrict tile, const int32_t* __restrict w0,
                   const int32_t* __restrict dy, int i0, int n, int line,
                   uint64_t (*__restrict w)[2][2 * Block<K>::kPixels]) {
  if (i0 == 0)
    for (int i = 0; i < std::min(line, kAhead); ++i)
      for (int k = 0; k < p.count; ++k) {
        const uint64_t* q = p.at(k, tile[i], w0[i]);
        __builtin_prefetch(q);
        __builtin_prefetch(q + dy[i]);
      }
  for (int i = 0; i < n; ++i) {
    const int j = i0 + i;
    if (j + kAhead < line)
      for (int k = 0; k < p.count; ++k) {
        const uint64_t* q = p.at(k, tile[j + kAhead], w0[j + kAhead]);
        __builtin_prefetch(q);
        __builtin_prefetch(q + dy[j + kAhead]);
      }
    for (int k = 0; k < p.count; ++k) {
      const uint64_t* q = p.at(k, tile[j], w0[j]);
      std::memcpy(&w[k][0][2 * i], q, 16);
      std::memcpy(&w[k][1][2 * i], q + dy[j], 16);
    }
  }
}

// Every tap composed across the memories: each row's 2 n words (the quads' top and bottom pairs), in place
// of the pairs: row0[2 i] is c00, row0[2 i + 1] c10, row1[2 i] c01, row1[2 i + 1] c11.
template <int K>
[[gnu::always_inline]] inline void compose_taps_body(const uint64_t (*__restrict w)[2][2 * Block<K>::kPixels],
                                                     int count_rt, int n, const CompositionParams& cpref,
                                                     uint32_t* __restrict row0, uint32_t* __restrict row1) {
  const int count = K > 0 ? K : count_rt;
  const CompositionParams cp = cpref;
  for (int j = 0; j < 2 * n; ++j) {
    uint64_t a[Block<K>::kMemories] = {}, b[Block<K>::kMemories] = {};
#pragma GCC unroll 8
    for (int k = 0; k < count; ++k) {
      a[k] = w[k][0][j];
      b[k] = w[k][1][j];
    }
    row0[j] = compose(a, count, cp).color;
    row1[j] = compose(b, count, cp).color;
  }
}

#define ARP_COMPOSE_TAPS(K)                                                                                        \
  ARP_VECTOR_CLONES void compose_taps_##K(const uint64_t (*w)[2][2 * Block<K>::kPixels], int count, int n,        \
                                          const CompositionParams& cp, uint32_t* row0, uint32_t* row1) {         \
    compose_taps_body<K>(w, count, n, cp, row0, row1);                                                           \
  }
ARP_COMPOSE_TAPS(2)
ARP_COMPOSE_TAPS(3)
ARP_COMPOSE_TAPS(4)
ARP_COMPOSE_TAPS(5)
ARP_COMPOSE_TAPS(6)
ARP_COMPOSE_TAPS(7)
ARP_COMPOSE_TAPS(8)
#undef ARP_COMPOSE_TAPS
void compose_taps_0(const uint64_t (*w)[2][2 * Block<0>::kPixels], int count, int n, const CompositionParams& cp,
                    uint32_t* row0, uint32_t* row1) {
  compose_taps_body<0>(w, count, n, cp, row0, row1);
}

// The blend over the composed rows (compose_taps_body's layout).
template <class Acc>
[[gnu::always_inline]] inline void blend_colours_body(const uint32_t* __restrict row0, const uint32_t* __restrict row1,
                                                      const uint32_t* __restrict wx, const uint32_t* __restrict wy,
                                                      int n, int T, const ChannelLayout& Lref,
                                                      uint32_t* __restrict out) {
  const ChannelLayout L = Lref;
  for (int i = 0; i < n; ++i)
    out[i] = bilinear_blend_in<Acc>(row0[2 * i], row0[2 * i + 1], row1[2 * i], row1[2 * i + 1], wx[i], wy[i], T, L);
}

ARP_VECTOR_CLONES
void blend_colours_32(const uint32_t* row0, const uint32_t* row1, const uint32_t* wx, const uint32_t* wy, int n, int T,
                      const ChannelLayout& L, uint32_t* out) {
  blend_colours_body<uint32_t>(row0, row1, wx, wy, n, T, L, out);
}

ARP_VECTOR_CLONES
void blend_colours_64(const uint32_t* row0, const uint32_t* row1, const uint32_t* wx, const uint32_t* wy, int n, int T,
                      const ChannelLayout& L, uint32_t* out) {
  blend_colours_body<uint64_t>(row0, row1, wx, wy, n, T, L, out);
}

template <int K, bool Dense>
void bilinear_memories_pass(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                            int T, int32_t S, const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  constexpr int B = Block<K>::kPixels;
  const Pools<K, Dense> p(src);
  // The whole line's taps first, so that the loads can look ahead across blocks.
  thread_local std::vector<int32_t> taps_of_thread;
  std::vector<int32_t>& taps = taps_of_thread;
  taps.resize(5 * static_cast<size_t>(n));
  int32_t* tile = taps.data();
  int32_t *w0 = tile + n, *dy = w0 + n;
  uint32_t* wx = reinterpret_cast<uint32_t*>(dy + n);
  uint32_t* wy = wx + n;
  bilinear_taps_impl(face, u, v, n, T, S, src.tiles_per_row, src.tiles_per_face, tile, w0, dy, wx, wy);
  alignas(64) uint32_t row0[2 * B], row1[2 * B];
  alignas(64) uint64_t words[Block<K>::kMemories][2][2 * B];
  const auto blend = blend_fits_32(T, L) ? blend_colours_32 : blend_colours_64;
  for (int i0 = 0; i0 < n; i0 += B) {
    const int m = std::min(B, n - i0);
    bilinear_load<K, Dense>(p, tile, w0, dy, i0, m, n, words);
    if constexpr (K == 2) compose_taps_2(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 3) compose_taps_3(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 4) compose_taps_4(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 5) compose_taps_5(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 6) compose_taps_6(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 7) compose_taps_7(words, p.count, m, cp, row0, row1);
    else if constexpr (K == 8) compose_taps_8(words, p.count, m, cp, row0, row1);
    else compose_taps_0(words, p.count, m, cp, row0, row1);
    blend(row0, row1, wx + i0, wy + i0, m, T, L, out + i0);
  }
}
template <int K>
void bilinear_memories_impl(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                            int T, int32_t S, const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  if (src.dense) bilinear_memories_pass<K, true>(src, face, u, v, n, T, S, L, cp, out);
  else bilinear_memories_pass<K, false>(src, face, u, v, n, T, S, L, cp, out);
}

template <bool Dense>
[[gnu::always_inline]] inline void nearest_single_body(const uint64_t* __restrict pool, const int32_t* __restrict offset,
                                                       const int32_t* __restrict face, const int32_t* __restrict u,
                                                       const int32_t* __restrict v, int n, int T, int tpr, int tpf,
                                                       const CompositionParams& cpref, uint32_t* __restrict out) {
  const CompositionParams cp = cpref;
  for (int i = 0; i < n; ++i) {
    const int32_t tx = u[i] >> T, ty = v[i] >> T;
    const int32_t tile = tile_of(face[i], tx, ty, tpr, tpf), word = word_of(tx, ty);
    // Dense: the tiles in table order (EyeSources::dense), the place arithmetic; else through the table.
    const uint64_t w = Dense ? pool[int64_t{tile} * DisplayMemoryBank::kTileWords + word] : texel(pool, offset, tile, word);
    out[i] = compose(&w, 1, cp).color;
  }
}

ARP_VECTOR_CLONES
void nearest_single_impl(const uint64_t* pool, const int32_t* offset, bool dense, const int32_t* face, const int32_t* u,
                         const int32_t* v, int n, int T, int tpr, int tpf, const CompositionParams& cp, uint32_t* out) {
  if (dense) nearest_single_body<true>(pool, offset, face, u, v, n, T, tpr, tpf, cp, out);
  else nearest_single_body<false>(pool, offset, face, u, v, n, T, tpr, tpf, cp, out);
}
}  // namespace

void bilinear_single_memory_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                                 int T, int32_t S, const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  bilinear_single_impl(src.dense ? src.dense_base[0] : src.pool[0], src.offset[0], src.dense, face, u, v, n, T, S,
                       src.tiles_per_row, src.tiles_per_face, L, cp, out);
}

void bilinear_memories_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n, int T,
                            int32_t S, const ChannelLayout& L, const CompositionParams& cp, uint32_t* out) {
  switch (src.count) {
    case 0: std::fill(out, out + n, cp.background); break;
    case 1: bilinear_single_memory_line(src, face, u, v, n, T, S, L, cp, out); break;
    case 2: bilinear_memories_impl<2>(src, face, u, v, n, T, S, L, cp, out); break;
    case 3: bilinear_memories_impl<3>(src, face, u, v, n, T, S, L, cp, out); break;
    case 4: bilinear_memories_impl<4>(src, face, u, v, n, T, S, L, cp, out); break;
    case 5: bilinear_memories_impl<5>(src, face, u, v, n, T, S, L, cp, out); break;
    case 6: bilinear_memories_impl<6>(src, face, u, v, n, T, S, L, cp, out); break;
    case 7: bilinear_memories_impl<7>(src, face, u, v, n, T, S, L, cp, out); break;
    case 8: bilinear_memories_impl<8>(src, face, u, v, n, T, S, L, cp, out); break;
    default: bilinear_memories_impl<0>(src, face, u, v, n, T, S, L, cp, out); break;
  }
}

void nearest_single_memory_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                                int T, const CompositionParams& cp, uint32_t* out) {
  nearest_single_impl(src.dense ? src.dense_base[0] : src.pool[0], src.offset[0], src.dense, face, u, v, n, T,
                      src.tiles_per_row, src.tiles_per_face, cp, out);
}

}  // namespace arp::passes
