#include "TearImage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace arp::host {

TearWindow densest_window(const ObjectMap& layout, const std::vector<uint8_t>& marks, uint8_t mark, int width, int height) {
  const int W = layout.width, H = layout.height;
  if (marks.size() != layout.id.size() || width <= 0 || height <= 0)
    throw std::invalid_argument("densest_window: marks of another size or an empty window");
  TearWindow best;
  best.width = std::min(width, W);
  best.height = std::min(height, H);
  const int ww = best.width, wh = best.height;
  // Summed-area table per eye: O(pixels) whatever the window.
  std::vector<int64_t> sat(static_cast<size_t>(W + 1) * static_cast<size_t>(H + 1));
  auto at = [&](int x, int y) -> int64_t& { return sat[static_cast<size_t>(y) * static_cast<size_t>(W + 1) + static_cast<size_t>(x)]; };
  for (int e = 0; e < layout.eyes; ++e) {
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        at(x + 1, y + 1) = at(x, y + 1) + at(x + 1, y) - at(x, y) + ((marks[layout.index(e, x, y)] & mark) ? 1 : 0);
    for (int y = 0; y + wh <= H; ++y)
      for (int x = 0; x + ww <= W; ++x) {
        const int64_t n = at(x + ww, y + wh) - at(x, y + wh) - at(x + ww, y) + at(x, y);
        if (n > best.marked) {
          best.marked = n;
          best.eye = e;
          best.x = x;
          best.y = y;
        }
      }
  }
  if (best.marked == 0) return best;
  // Centre the window on the marked pixels it holds, so the place is in the middle, not at an edge.
  double cx = 0, cy = 0;
  for (int y = best.y; y < best.y + wh; ++y)
    for (int x = best.x; x < best.x + ww; ++x)
      if (marks[layout.index(best.eye, x, y)] & mark) {
        cx += x;
        cy += y;
      }
  cx /= static_cast<double>(best.marked);
  cy /= static_cast<double>(best.marked);
  best.x = std::clamp(static_cast<int>(std::floor(cx + 0.5)) - ww / 2, 0, W - ww);
  best.y = std::clamp(static_cast<int>(std::floor(cy + 0.5)) - wh / 2, 0, H - wh);
  best.marked = 0;
  for (int y = best.y; y < best.y + wh; ++y)
    for (int x = best.x; x < best.x + ww; ++x) best.marked += (marks[layout.index(best.eye, x, y)] & mark) ? 1 : 0;
  return best;
}

RgbImage magnified_tear(const RgbImage& shown, const RgbImage& truth, const ObjectMap& layout,
                        const std::vector<uint8_t>& marks, const TearWindow& w, int scale) {
  if (scale < 1 || w.width <= 0 || w.height <= 0 || w.x < 0 || w.y < 0 || w.x + w.width > layout.width ||
      w.y + w.height > layout.height || w.eye < 0 || w.eye >= layout.eyes || marks.size() != layout.id.size())
    throw std::invalid_argument("magnified_tear: window outside the frame");
  for (const RgbImage* img : {&shown, &truth})
    if (img->width != layout.width * layout.eyes || img->height != layout.height)
      throw std::invalid_argument("magnified_tear: frame image of another size");
  constexpr int kGap = 4;  // dark grey between the panels
  const int pw = w.width * scale, ph = w.height * scale;
  RgbImage out(3 * pw + 2 * kGap, ph);
  std::fill(out.rgb.begin(), out.rgb.end(), uint8_t{48});
  for (int panel = 0; panel < 3; ++panel)
    for (int y = 0; y < w.height; ++y)
      for (int x = 0; x < w.width; ++x) {
        const int fx = w.eye * layout.width + w.x + x, fy = w.y + y;
        uint8_t c[3];
        std::copy_n((panel == 1 ? truth : shown).px(fx, fy), 3, c);
        if (panel == 2) {
          const uint8_t m = marks[layout.index(w.eye, w.x + x, w.y + y)];
          if (m & kCrackMark) {
            c[0] = 255; c[1] = 0; c[2] = 255;
          } else if (m & kTearMark) {
            c[0] = 255; c[1] = 255; c[2] = 0;
          } else if (m & kSeamZone) {  // a cyan tint shows where the seams run
            c[0] = static_cast<uint8_t>(c[0] / 2);
            c[1] = static_cast<uint8_t>(c[1] / 2 + 128);
            c[2] = static_cast<uint8_t>(c[2] / 2 + 128);
          }
        }
        for (int sy = 0; sy < scale; ++sy)
          for (int sx = 0; sx < scale; ++sx) std::copy_n(c, 3, out.px(panel * (pw + kGap) + x * scale + sx, y * scale + sy));
      }
  return out;
}

}  // namespace arp::host
