// The per-pixel half of the llvmpipe comparison: what asynchronous time warp
// does on a GPU, written as lean as OpenGL allows, doing the functional
// model's work on the same display memories -- lens vector from gl_FragCoord
// (the lens table's formula), the orientation the model's latch rule picks
// for each line (rows of the quantised register, one uniform block),
// rotation, a cube-map fetch from each written display memory (nearest or
// bilinear) and the nearest depth wins, read back as [eye][y][x] RGBA8 --
// the layout and size of an HmdFrame. Each eye is one full-screen triangle
// over its own rows with its own memories bound.
//
// A display memory is a cube texture per eye: RGBA8 with the depth code's
// high byte in alpha (the leanest texel), or RGBA16 with the whole 16-bit
// code (arpsim's own 64-bit texel). Alpha 1.0 is "empty" in both.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rtl_model/functional/FunctionalModel.hpp"

namespace arp::bench {

struct PerPixelSetup {
  int memories = 1;      // written display memories composed per pixel
  bool bilinear = false;
  bool wide_texel = false;  // RGBA16 (16-bit depth) instead of RGBA8 (depth's high byte)
};

class GlPerPixel {
 public:
  // A current GL context is needed (host::EglContext). The memories' front buffers are uploaded once.
  GlPerPixel(const FunctionalModel& model, const dp::DisplayMemorySet& mem, const PerPixelSetup& setup);
  ~GlPerPixel();
  GlPerPixel(const GlPerPixel&) = delete;
  GlPerPixel& operator=(const GlPerPixel&) = delete;

  // Frame `frame` under `orientation`, read back into `rgba` ([eye][y][x], R in the lowest byte).
  void render(const dp::OrientationStream& orientation, int64_t frame, std::vector<uint32_t>& rgba);

 private:
  struct Gl;
  const FunctionalModel& model_;
  PerPixelSetup setup_;
  std::unique_ptr<Gl> gl_;
};

}  // namespace arp::bench
