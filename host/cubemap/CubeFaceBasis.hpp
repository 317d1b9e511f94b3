// How a face image is looked at. Face images (six files, the cross layout,
// the calibration pattern) are the views from the cube's centre along each
// face axis, upright and unmirrored, in the head frame (x right, y up, front
// is -z). Unfolded as a horizontal cross they read:
//
//            [+Y up]
//   [-X left][-Z front][+X right][+Z back]
//            [-Y down]
//
// The display memory itself follows the OpenGL cube-map table (a mirror of
// these views); the mapping between the two goes through directions, so it
// cannot drift from the address generator's convention.
#pragma once
#include <array>

namespace arp::host {

struct Dir3 {
  double x, y, z;
};

struct FaceBasis {
  Dir3 forward, up, right;
};

inline const std::array<FaceBasis, 6>& face_bases() {
  static const std::array<FaceBasis, 6> b{{
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},     // +X right
      {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}},   // -X left
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},     // +Y up (image top toward the back)
      {{0, -1, 0}, {0, 0, -1}, {1, 0, 0}},   // -Y down (image top toward the front)
      {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}},    // +Z back
      {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},    // -Z front
  }};
  return b;
}

// Direction of the centre of display-memory texel (x, y) of `face` (GL table, inverted).
Dir3 memory_texel_direction(int face, int x, int y, int face_size);

}  // namespace arp::host
