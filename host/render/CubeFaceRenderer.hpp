// Renders a scene into the six faces of a display memory's back buffer, as
// seen from one eye position: for face f the 90-degree frustum whose texel
// (x, y) centre looks along memory_texel_direction(f, x, y) -- the address
// generator's own convention (OpenGL cube-map table), so a rendered point
// lands where the pipeline will look for it.
//
// - Clipping: every triangle is clipped to the face's frustum, near plane
//   included (DepthCode::near_m), in homogeneous coordinates.
// - Fill rule: vertices are snapped to 1/256 texel and edges evaluated in
//   64-bit integers at texel centres; a centre exactly on an edge belongs to
//   the triangle for which that edge is a "top or left" edge (direction
//   (dy > 0) or (dy == 0 and dx < 0) in face coordinates), so two triangles
//   sharing an edge cover each centre on it exactly once -- no cracks, no
//   double hits. Both windings are drawn (walls are seen from both sides).
// - Depth: radial distance from the eye, perspective-correct, nearest wins
//   (the first drawn on an exact tie); stored as a DepthCode.
// - Shading: a fixed light; flat (the triangle's normal) or Gouraud (vertex
//   normals, perspective-correct), colour quantised by the memory's format.
// Results are deterministic: doubles without fast-math, a fixed order within
// each face, and faces drawn independently (in parallel: set_threads).
// A face no object's bounding sphere can reach is not rendered at all.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "DepthCode.hpp"
#include "host/scene/Scene.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::host {

struct RenderStats {
  int64_t objects = 0;            // objects drawn (on at least one face)
  int64_t triangles = 0;          // triangles submitted, once per face the object's bound reaches
  int64_t texels_filled = 0;      // texels that passed the depth test, summed over triangles
  int64_t texels_written = 0;     // texels stored in the memory
  int faces_rendered = 0;
  // Only with CubeFaceRenderer::set_fill_by_object(true): texels_filled by object (scene index), summed over
  // the faces; the entries add up to texels_filled.
  std::vector<int64_t> filled_by_object;
};

struct LightModel {
  glm::dvec3 direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.45));  // toward the light
  double ambient = 0.35, diffuse = 0.65;
};

// One face's render target: radial distance and colour per texel (both
// empty for a face nothing reached).
struct FaceImage {
  int size = 0;
  std::vector<double> distance;  // +inf where nothing was drawn
  std::vector<glm::dvec3> color;  // linear 0..1
  std::vector<uint32_t> object;   // the visible object per texel: its scene index + 1 (0: nothing)
  std::vector<uint16_t> hits;     // if sized by the caller: how many triangles covered each texel centre (tests)
  void reset(int s);
};

// Moves a world-space vertex of object i before it is drawn (region warping).
using VertexWarp = std::function<glm::dvec3(size_t object, const glm::dvec3& world)>;

class CubeFaceRenderer {
 public:
  explicit CubeFaceRenderer(DepthCode depth = {}, LightModel light = {}) : depth_(depth), light_(light) {}

  // Renders `objects` (indices into scene.objects; all if empty) at time t
  // from `eye` into the bank's back buffer, which is cleared first; commits.
  // `visible`, if given, receives the six faces' visible objects (FaceImage::object; distance and colour left empty).
  RenderStats render(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye,
                     dp::DisplayMemoryBank& bank, std::vector<FaceImage>* visible = nullptr,
                     const VertexWarp* warp = nullptr) const;

  // The same drawing into six float faces of any size (ground truth, tests).
  RenderStats render_faces(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye,
                           int face_size, std::vector<FaceImage>& faces, const VertexWarp* warp = nullptr) const;

  // What render() would submit -- objects, triangles, faces -- without drawing (no fill count).
  RenderStats count(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye) const;

  const DepthCode& depth() const { return depth_; }
  // Threads drawing faces (one face each) and storing them: 0, every hardware thread. Any count gives the same bits.
  void set_threads(int n) { threads_ = n; }
  // Off: every object is drawn on all six faces and clipped there (the same texels, more work).
  void set_face_culling(bool on) { cull_faces_ = on; }
  // On: render_faces() and render() also count the fill by object (RenderStats::filled_by_object).
  void set_fill_by_object(bool on) { fill_by_object_ = on; }

 private:
  DepthCode depth_;
  LightModel light_;
  int threads_ = 0;
  bool cull_faces_ = true;
  bool fill_by_object_ = false;
};

}  // namespace arp::host
