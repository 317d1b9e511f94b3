#include "CalibrationPattern.hpp"

#include <algorithm>
#include <string>

#include "BitmapFont.hpp"

namespace arp::host {

const std::array<std::array<int, 3>, 6>& calibration_face_colors() {
  static const std::array<std::array<int, 3>, 6> c{{
      {{200, 60, 60}},    // +X red
      {{60, 190, 190}},   // -X cyan
      {{70, 190, 70}},    // +Y green
      {{190, 70, 190}},   // -Y magenta
      {{70, 90, 210}},    // +Z blue
      {{210, 190, 60}},   // -Z yellow
  }};
  return c;
}

const char* calibration_face_word(int face) {
  static const char* w[6] = {"RIGHT", "LEFT", "UP", "DOWN", "BACK", "FRONT"};
  return face >= 0 && face < 6 ? w[face] : "";
}

CubeMapImages make_calibration_pattern(int S) {
  static const char* axis[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  CubeMapImages cm;
  cm.face_size = S;
  const int fine = std::max(1, S / 16), coarse = std::max(1, S / 4);
  const int border = std::max(1, S / 256);
  for (int f = 0; f < 6; ++f) {
    RgbImage img(S, S);
    const auto& base = calibration_face_colors()[static_cast<size_t>(f)];
    auto set = [&](int x, int y, int r, int g, int b) {
      if (x < 0 || y < 0 || x >= S || y >= S) return;
      uint8_t* p = img.px(x, y);
      p[0] = static_cast<uint8_t>(r); p[1] = static_cast<uint8_t>(g); p[2] = static_cast<uint8_t>(b);
    };
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        const bool edge = x < border || y < border || x >= S - border || y >= S - border;
        const bool heavy = (x % coarse) < border || (y % coarse) < border;
        const bool light = x % fine == 0 || y % fine == 0;
        if (edge) set(x, y, 255, 255, 255);
        else if (heavy) set(x, y, base[0] / 3, base[1] / 3, base[2] / 3);
        else if (light) set(x, y, base[0] * 2 / 3, base[1] * 2 / 3, base[2] * 2 / 3);
        else set(x, y, base[0], base[1], base[2]);
      }
    auto ink = [&](int x, int y) { set(x, y, 16, 16, 16); };
    const int big = std::max(1, S / 48), small = std::max(1, S / 96);
    const std::string a = axis[f], word = calibration_face_word(f);
    draw_text(a, (S - text_width(a, big)) / 2, S / 2 - 8 * big, big, ink);
    draw_text(word, (S - text_width(word, small)) / 2, S / 2 + 2 * small, small, ink);
    draw_text("^", (S - text_width("^", small)) / 2, S / 8, small, ink);
    cm.faces[static_cast<size_t>(f)] = std::move(img);
  }
  return cm;
}

}  // namespace arp::host
