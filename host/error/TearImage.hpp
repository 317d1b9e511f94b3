// A magnified look at tearing: the window of the display holding the most
// marked seam pixels, shown as three panels scaled up with square pixels --
// the displayed frame, the ground truth, and the displayed frame with crack
// pixels in magenta, tear pixels in yellow and the rest of the seam zone
// tinted cyan.
#pragma once
#include <cstdint>

#include "host/cubemap/CubeMapImages.hpp"
#include "SeamMetrics.hpp"

namespace arp::host {

struct TearWindow {
  int eye = 0, x = 0, y = 0, width = 0, height = 0;
  int64_t marked = 0;  // pixels inside carrying the mark
};

// A width x height window (clamped to the eye's image) holding the most pixels
// carrying `mark` (the first in eye, row, column order on ties), then centred
// on the marked pixels inside it; marked = 0 when there are none.
TearWindow densest_window(const ObjectMap& layout, const std::vector<uint8_t>& marks, uint8_t mark, int width, int height);

// shown and truth are whole frames with the eyes side by side (eye e's pixel
// (x, y) at column e * layout.width + x), as the run's frame images are.
RgbImage magnified_tear(const RgbImage& shown, const RgbImage& truth, const ObjectMap& layout,
                        const std::vector<uint8_t>& marks, const TearWindow& w, int scale);

}  // namespace arp::host
