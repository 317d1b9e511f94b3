// The six cube faces as render targets, in the display memory's own
// convention (the OpenGL cube-map table, memory_texel_direction inverted):
// the centre of texel (x, y) of face f looks along fwd + sc a + tc b with
// sc = 2 (x + 1/2) / S - 1 and tc = 2 (y + 1/2) / S - 1. Every renderer
// (software, OpenGL) draws through these frames and culls with the same test.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "host/scene/Scene.hpp"

namespace arp::host {

struct FaceFrame {
  glm::dvec3 fwd, a, b;
};

const std::array<FaceFrame, 6>& face_frames();

// Can a sphere (centre relative to the eye, radius r) reach face f's 90-degree
// frustum beyond the near distance? Conservative: true may still draw nothing.
bool sphere_meets_face(const glm::dvec3& center, double r, int face, double near_m);

// What a render at time t from `eye` submits: per face, the objects (indices into scene.objects, `objects`,
// or all if it is empty) whose bound reaches it, in scene order (deterministic ties); each drawn object's
// model matrix at t; how many objects reach any face. `cull` false: every object on every face (what the
// culling saves is measured against it: bench/culling-gating.sh).
struct FaceLists {
  std::array<std::vector<size_t>, 6> per_face;
  std::vector<glm::dmat4> model;  // by scene index, set for the objects drawn
  std::vector<char> drawn;        // by scene index
  int64_t objects = 0;
};
FaceLists cull_to_faces(const Scene& scene, const std::vector<size_t>& objects, double t_s, const glm::dvec3& eye,
                        double near_m, bool cull = true);

}  // namespace arp::host
