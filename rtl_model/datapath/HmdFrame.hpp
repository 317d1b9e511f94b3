// One scanned-out stereo (or mono) HMD frame: display colour per pixel,
// packed R:G:B with display_bits each, and optionally each pixel's photon time.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace arp {

struct HmdFrame {
  int width = 0, height = 0, eyes = 0, display_bits = 8;
  int64_t frame_index = 0;
  std::vector<uint32_t> pixels;     // [eye][y][x]
  std::vector<int64_t> photon_ps;   // same layout, empty unless requested

  void resize(int w, int h, int e, bool photon_times) {
    width = w; height = h; eyes = e;
    pixels.assign(static_cast<size_t>(w) * h * e, 0);
    if (photon_times) photon_ps.assign(pixels.size(), 0); else photon_ps.clear();
  }
  // As resize, for a producer that writes every pixel (and every photon time when asked): the old
  // values are left for it to overwrite, not cleared first (7 MB a stereo VGA frame).
  void resize_to_overwrite(int w, int h, int e, bool photon_times) {
    width = w; height = h; eyes = e;
    pixels.resize(static_cast<size_t>(w) * h * e);
    if (photon_times) photon_ps.resize(pixels.size()); else photon_ps.clear();
  }
  size_t index(int eye, int x, int y) const {
    return (static_cast<size_t>(eye) * height + static_cast<size_t>(y)) * width + static_cast<size_t>(x);
  }
  uint32_t at(int eye, int x, int y) const { return pixels[index(eye, x, y)]; }
  // Channel c (0 red, 1 green, 2 blue) of a pixel.
  uint32_t channel(int eye, int x, int y, int c) const {
    return (at(eye, x, y) >> ((2 - c) * display_bits)) & ((1u << display_bits) - 1);
  }
};

}  // namespace arp
