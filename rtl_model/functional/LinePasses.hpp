// The functional model's scanline passes. Each pass is a plain loop over one
// line that calls the datapath's own inline stage functions, so the compiler
// can vectorise it; the result is bit-identical to calling the stages pixel by
// pixel (tests/FunctionalModelTest proves it). Passes that vectorise are
// compiled for x86-64-v4 (AVX-512) and a portable baseline, chosen at run time.
//
// Per strip of a line: rotate -> address (face, texel-space u, v) -> then,
// for an eye whose scene sits in one memory, fused passes (tap addresses,
// texel loads, composition, blend); for several memories, tap addresses ->
// fetch and composite (per tap for nearest; the four taps of a pixel at once
// for bilinear) -> blend. Scan-out last.
#pragma once
#include <cstdint>

#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::passes {

// The reciprocal unit tabulated over its whole input domain: entry m is
// exactly dp::aligned_reciprocal(dp::reciprocal(m)). Built only when the
// domain is small (rot_frac <= 15) and entries fit 32 bits.
struct ReciprocalMemo {
  const uint32_t* aligned = nullptr;
  bool int32_lanes = false;  // dp::address_fits_int32: the generator's arithmetic in 32-bit lanes
  bool valid() const { return aligned != nullptr; }
};

// The display memories one eye composites, in index order: those with any
// face written. A face a memory never wrote reads tile 0 (the empty tile),
// so leaving out only wholly unwritten memories changes no result. Each
// memory's tiles are flattened over its six faces (tile face * tiles_per_face
// + row * tiles_per_row + column) and given as word offsets into its pool
// (tile number * 1089, below 2^31 for every valid face size), so a texel is
// pool[offset[tile] + word] with word = row * 33 + column (DisplayMemoryBank).
struct EyeSources {
  int count = 0;
  const uint64_t* pool[16];
  const int32_t* offset[16];
  int tiles_per_row = 0, tiles_per_face = 0;
  // Every memory's tiles in its pool in table order (offset[k][t] == offset[k][0] + t x kTileWords for
  // every t): a texel of tile t is then dense_base[k] + t x kTileWords + word, the same arithmetic for
  // every memory (the passes skip the tile tables: one dependent load a texel less).
  bool dense = false;
  const uint64_t* dense_base[16];
};

// Orientation matrix unit over [x0, x1): lens vectors -> rotated vectors. int32_lanes: the accumulators
// in 32 bits, for configurations dp::rotate_fits_int32 admits (the same results, twice the lanes).
void rotate_line(const dp::Mat3q& M, const int32_t* lx, const int32_t* ly, const int32_t* lz, int x0, int x1,
                 const dp::RotateParams& p, bool int32_lanes, int32_t* rx, int32_t* ry, int32_t* rz);

// Cube-face address generator over a line: face and texel-space position
// (Q.texel_frac; below 2^30 for every valid configuration, so 32 bits).
void address_line_lut(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n,
                      const dp::AddressGeneratorParams& p, const ReciprocalMemo& memo, int32_t* face, int32_t* u,
                      int32_t* v);
void address_line_exact(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n,
                        const dp::AddressGeneratorParams& p, int32_t* face, int32_t* u, int32_t* v);

// Where a texel lives: tile number in the flattened six-face table, word within the tile.
struct TexelRef {
  int32_t* tile;
  int32_t* word;
};

// Nearest texel of each pixel.
void nearest_refs_line(const int32_t* face, const int32_t* u, const int32_t* v, int n, int texel_frac,
                       const EyeSources& src, TexelRef out);
// The whole bilinear path for an eye with a single memory, per block of
// pixels: tap positions (the tiles' aprons put all four taps in one tile),
// the texel loads, composition and blend. out is the memory-colour code per pixel.
void bilinear_single_memory_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                                 int texel_frac, int32_t face_size, const dp::ChannelLayout& L,
                                 const dp::CompositionParams& cp, uint32_t* out);
// The bilinear path for any number of memories (one: the above): per block,
// tap positions, per pixel and memory one tile lookup and the four taps,
// composited per tap, then the blend.
void bilinear_memories_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                            int texel_frac, int32_t face_size, const dp::ChannelLayout& L,
                            const dp::CompositionParams& cp, uint32_t* out);
// The nearest-texel path for an eye with a single memory, fused likewise.
void nearest_single_memory_line(const EyeSources& src, const int32_t* face, const int32_t* u, const int32_t* v, int n,
                                int texel_frac, const dp::CompositionParams& cp, uint32_t* out);

// Fetch from every memory of the eye and composite (any src.count).
void fetch_compose_line(const EyeSources& src, TexelRef ref, int n, const dp::CompositionParams& cp, uint32_t* out);

}  // namespace arp::passes
