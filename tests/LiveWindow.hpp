// `arpsim live`'s window as the tests see it: run under Xvfb, and its
// screenshot compared with the pipeline's frame outside the overlay box.
#pragma once
#include <cstdint>
#include <string>

#include "host/cubemap/CubeMapImages.hpp"

namespace arp::test {

// Runs a command under a virtual X server. In the sanitizer build the window's process is not leak-checked:
// SDL leaves allocations behind in libdbus and in display back-ends it loads and unloads itself (not ours;
// ASan still checks its memory accesses).
inline const std::string kXvfbRun =
    "env ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" xvfb-run -a -s '-screen 0 1600x1000x24' ";

struct OverlayComparison {
  int box_w = 0, box_h = 0;  // the overlay box, top-left: dark (16) with white text
  int64_t text = 0;          // white pixels in it
  int64_t differ = 0;        // pixels outside it unlike the frame's
};

inline OverlayComparison compare_outside_overlay(const host::RgbImage& shot, const host::RgbImage& frame) {
  OverlayComparison c;
  while (c.box_w < shot.width && shot.px(c.box_w, 1)[0] == 16) ++c.box_w;
  while (c.box_h < shot.height && shot.px(1, c.box_h)[0] == 16) ++c.box_h;
  for (int y = 0; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x) {
      const uint8_t* a = shot.px(x, y);
      if (x < c.box_w && y < c.box_h) {
        c.text += a[0] == 255 && a[1] == 255 && a[2] == 255;
        continue;
      }
      const uint8_t* b = frame.px(x, y);
      c.differ += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
    }
  return c;
}

}  // namespace arp::test
