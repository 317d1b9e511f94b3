// The six cube faces as render targets, in the display memory's own
// convention (the OpenGL cube-map table, memory_texel_direction inverted):
// the centre of texel (x, y) of face f looks along fwd + sc a + tc b with
// sc = 2 (x + 1/2) / S - 1 and tc = 2 (y + 1/2) / S - 1. Every renderer
// (software, OpenGL) draws through these frames and culls with the same test.
#pragma once
#include <glm/glm.hpp>

#include <array>

namespace arp::host {

struct FaceFrame {
  glm::dvec3 fwd, a, b;
};

const std::array<FaceFrame, 6>& face_frames();

// Can a sphere (centre relative to the eye, radius r) reach face f's 90-degree
// frustum beyond the near distance? Conservative: true may still draw nothing.
bool sphere_meets_face(const glm::dvec3& center, double r, int face, double near_m);

}  // namespace arp::host
