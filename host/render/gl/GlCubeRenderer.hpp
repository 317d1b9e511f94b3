// The cube faces rendered by OpenGL (`--renderer gl`): the same scene, faces,
// culling, shading and depth code as CubeFaceRenderer, drawn through an EGL
// surfaceless context (the GPU when the machine has one, llvmpipe otherwise)
// and read back into the display memory. The software renderer stays the
// default and the deterministic reference; this one differs from it where
// the rasterisers differ (float vertices, GL's fill rule, depth tested on the
// z-buffer and coded from the interpolated radial distance, both in float),
// measured in tests/GlRendererTest.
//
// Meshes and textures are uploaded once (vertex positions in the model frame,
// flat-shaded meshes expanded to one normal per triangle); each draw carries
// the model transform relative to the eye, computed in double, so a view far
// from the origin renders as at the origin.
#pragma once
#include <memory>
#include <vector>

#include "EglContext.hpp"
#include "host/render/CubeFaceRenderer.hpp"

namespace arp::host {

class GlCubeRenderer {
 public:
  // The widest depth code the fragment shader computes exactly: it codes in float (a 24-bit significand).
  static constexpr int kMaxDepthBits = 24;

  // GlUnavailable if EGL or OpenGL 3.3 cannot be had.
  explicit GlCubeRenderer(DepthCode depth = {}, LightModel light = {}, const EglOptions& egl = {});
  ~GlCubeRenderer();
  GlCubeRenderer(const GlCubeRenderer&) = delete;
  GlCubeRenderer& operator=(const GlCubeRenderer&) = delete;

  // As CubeFaceRenderer::render (no vertex warp): the bank's back buffer is
  // cleared, the six faces drawn and read back, then committed.
  RenderStats render(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye,
                     dp::DisplayMemoryBank& bank, std::vector<FaceImage>* visible = nullptr);

  // Only the OpenGL part (std::invalid_argument for depth_bits above kMaxDepthBits): the six faces drawn and read back into the renderer's
  // own RGBA8 and depth-code/object buffers (texels_written stays 0) -- what a
  // GL user has before anything is stored in a display memory.
  RenderStats draw(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye,
                   int face_size, int depth_bits);

  // Threads converting the read-back faces into memory words (0: every hardware thread), as
  // CubeFaceRenderer::set_threads; OpenGL's own threads are EglOptions::threads.
  void set_threads(int n) { threads_ = n; }
  void set_face_culling(bool on) { cull_faces_ = on; }  // as CubeFaceRenderer's

  const EglContext& context() const;
  const DepthCode& depth() const { return depth_; }

 private:
  struct Gl;
  DepthCode depth_;
  LightModel light_;
  std::unique_ptr<Gl> gl_;
  std::vector<uint64_t> words_;
  int threads_ = 0;  // the six faces' texel words, stored into the bank after the readback
  bool cull_faces_ = true;
};

}  // namespace arp::host
