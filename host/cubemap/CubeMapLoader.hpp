// Loading a cube map from image files (through OpenImageIO) into the
// inside-view face images of CubeFaceBasis.hpp:
//  - six face images, each face_size x face_size;
//  - a cross: horizontal (4S x 3S, layout in CubeFaceBasis.hpp) or vertical
//    (3S x 4S: +Y / -X -Z +X / -Y / +Z, the back face turned 180 degrees);
//  - an equirectangular panorama (2:1, any size; longitude 0 is the front,
//    increasing to the right; resampled bilinearly to S x S faces).
// Every failure is an InputError naming the file and the reason.
#pragma once
#include <array>
#include <string>

#include "CubeMapImages.hpp"

namespace arp::host {

CubeMapImages load_six_faces(const std::array<std::string, 6>& paths, int face_size);
CubeMapImages load_cross(const std::string& path, int face_size);
CubeMapImages load_equirect(const std::string& path, int face_size);

// The six faces of a folder: files named px, nx, py, ny, pz, nz (any image extension).
std::array<std::string, 6> six_face_paths_in(const std::string& folder);

}  // namespace arp::host
