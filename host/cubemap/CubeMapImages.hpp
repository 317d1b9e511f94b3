// Six square RGB8 face images in the inside-view convention of CubeFaceBasis.hpp.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace arp::host {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, row 0 at the top
  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0) {}
  uint8_t* px(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
  const uint8_t* px(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

struct CubeMapImages {
  int face_size = 0;
  std::array<RgbImage, 6> faces;  // order +X -X +Y -Y +Z -Z
};

}  // namespace arp::host
