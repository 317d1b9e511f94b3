// Which texels of a cube face an object can cover: a conservative rectangle, from its mesh's box, for
// eyes anywhere within a margin of a point. What `arpsim plan` bounds a tile-sparse display memory with
// (the tiles any object of a memory can reach over the motion), tested against the renderer's own texels.
#pragma once
#include <glm/glm.hpp>

#include <array>

#include "host/scene/Scene.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::host {

// Texels [x0, x1] x [y0, y1] of a face, inclusive; empty when x1 < x0.
struct TexelRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
};

// Calls visit(tx, ty) for each 32 x 32 display-memory tile the rectangle touches, row by row, until one call
// returns false; whether none did (true for an empty rectangle).
template <class Visit>
bool each_tile(const TexelRect& r, Visit&& visit) {
  constexpr int kShift = dp::DisplayMemoryBank::kTileShift;
  if (r.empty()) return true;
  for (int ty = r.y0 >> kShift; ty <= r.y1 >> kShift; ++ty)
    for (int tx = r.x0 >> kShift; tx <= r.x1 >> kShift; ++tx)
      if (!visit(tx, ty)) return false;
  return true;
}

// How far any point of object o can move by its own animation (spin about its position, path) in dt seconds
// from time t, metres: an upper bound, the spin's arc at its bound's far side plus the path's speed.
double animation_reach_m(const SceneObject& o, double t_s, double dt_s);

// The model frame's axis-aligned box of a mesh's vertices: {min, max} (both 0 for no vertices).
std::array<glm::dvec3, 2> mesh_box(const Mesh& m);

// The texels of face f (S x S, FaceFrustum's convention) that object o, at time t, can cover for an eye
// anywhere within `margin_m` of `eye` (per coordinate): its model box placed at t, the world box around
// that grown by the margin, clipped at the near distance of the face's frustum and projected; the
// rectangle around the projection, one texel wider each side (a snapped vertex moves the outline by up to
// a texel). Conservative: the renderer writes no texel of the face outside it (an animated object only at
// t itself). `box`: mesh_box(*o.mesh), passed in so that callers over many times compute it once.
TexelRect object_face_rect(const SceneObject& o, const std::array<glm::dvec3, 2>& box, double t_s, const glm::dvec3& eye,
                           double margin_m, int face, int S, double near_m);

}  // namespace arp::host
