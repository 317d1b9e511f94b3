// A 5x7 bitmap font for the calibration pattern's labels. Built in rather
// than OpenImageIO's render_text, which needs a TrueType font installed: the
// pattern must be bit-identical on every machine so tests can compare it.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "CubeMapImages.hpp"

namespace arp::host {

constexpr int kGlyphW = 5, kGlyphH = 7;

// Calls plot(x, y) for every lit font pixel of `text` drawn with its top-left
// at (x0, y0), each font pixel a scale x scale block, one blank column between glyphs.
// Characters without a glyph are drawn as a filled box so a missing glyph is visible.
void draw_text(const std::string& text, int x0, int y0, int scale, const std::function<void(int, int)>& plot);
int text_width(const std::string& text, int scale);

// A dark box with white text (in the font's capitals) in the image's top-left corner.
void draw_text_box(RgbImage& img, const std::vector<std::string>& lines);

}  // namespace arp::host
