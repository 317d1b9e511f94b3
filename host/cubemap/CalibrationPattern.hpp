// The built-in calibration cube map: every face in its own colour, gridded
// every S/16 texels (heavier every S/4, a white border), labelled with its
// axis and its direction word (e.g. "-Z" / "FRONT") and an arrow pointing to
// the image's up, so a wrong face, a flip or a rotation is obvious at a glance.
#pragma once
#include <array>

#include "CubeMapImages.hpp"

namespace arp::host {

// Base colour of each face, RGB8, order +X -X +Y -Y +Z -Z.
const std::array<std::array<int, 3>, 6>& calibration_face_colors();
const char* calibration_face_word(int face);

CubeMapImages make_calibration_pattern(int face_size);

}  // namespace arp::host
