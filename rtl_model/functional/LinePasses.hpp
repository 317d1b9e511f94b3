// The functional model's scanline passes. Each pass is a plain loop over one
// line that calls the datapath's own inline stage functions, so the compiler
// can vectorise it; the result is bit-identical to calling the stages pixel by
// pixel (tests/FunctionalModelTest proves it). Passes that vectorise are
// compiled for x86-64-v4 (AVX-512) and a portable baseline, chosen at run time.
#pragma once
#include <cstdint>

#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::passes {

// The reciprocal unit tabulated over its whole input domain: entry m is
// exactly dp::reciprocal(m). Built only when the domain is small (rot_frac <= 15).
struct ReciprocalMemo {
  const uint32_t* y = nullptr;
  const int32_t* n = nullptr;  // 32-bit: byte gathers do not vectorise
  bool valid() const { return y != nullptr; }
};

// Orientation matrix unit over [x0, x1): lens vectors -> rotated vectors.
void rotate_line(const dp::Mat3q& M, const int32_t* lx, const int32_t* ly, const int32_t* lz, int x0, int x1,
                 const dp::RotateParams& p, int32_t* rx, int32_t* ry, int32_t* rz);

// Cube-face address generator over a whole line: face and texel-space position (Q.texel_frac).
void address_line_lut(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n,
                      const dp::AddressGeneratorParams& p, const ReciprocalMemo& memo, uint8_t* face, int64_t* u,
                      int64_t* v);
void address_line_exact(const int32_t* rx, const int32_t* ry, const int32_t* rz, int n,
                        const dp::AddressGeneratorParams& p, uint8_t* face, int64_t* u, int64_t* v);

// Bilinear blend of four composited colours per pixel.
void blend_line(const uint32_t* c00, const uint32_t* c10, const uint32_t* c01, const uint32_t* c11,
                const uint32_t* wx, const uint32_t* wy, int n, int texel_frac, const dp::ChannelLayout& L,
                uint32_t* out);

// The display memories one eye composites, in index order: those with any
// face written. A face a memory never wrote reads through the shared empty
// table, so leaving out only wholly unwritten memories changes no result.
struct EyeSources {
  int count = 0;
  const uint64_t* const* tables[6][16];
  int tiles_per_row = 0;
};

// Composition unit at each pixel's nearest texel (AA off): composited colour per pixel.
void compose_nearest_line(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n,
                          int texel_frac, const dp::CompositionParams& cp, uint32_t* out);

// Composition at the four bilinear taps of each pixel, and the tap weights.
void compose_bilinear_line(const EyeSources& src, const uint8_t* face, const int64_t* u, const int64_t* v, int n,
                           int texel_frac, int32_t face_size, const dp::CompositionParams& cp, uint32_t* c00,
                           uint32_t* c10, uint32_t* c01, uint32_t* c11, uint32_t* wx, uint32_t* wy);

}  // namespace arp::passes
