#include "sim/FrameImage.hpp"

namespace arp::sim {

host::RgbImage frame_to_image(const HmdFrame& f) {
  host::RgbImage img(f.width * f.eyes, f.height);
  const uint32_t dmax = (1u << f.display_bits) - 1;
  for (int e = 0; e < f.eyes; ++e)
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        uint8_t* p = img.px(e * f.width + x, y);
        for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>((f.channel(e, x, y, c) * 255u * 2 + dmax) / (2 * dmax));
      }
  return img;
}

}  // namespace arp::sim
