#include "CubeMapLoader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "CubeFaceBasis.hpp"
#include "ImageFiles.hpp"
#include "common/InputError.hpp"
#include "common/Units.hpp"

namespace arp::host {

namespace fs = std::filesystem;

namespace {

std::string size_str(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

RgbImage crop(const RgbImage& src, int x0, int y0, int S, bool rotate180) {
  RgbImage out(S, S);
  for (int y = 0; y < S; ++y)
    for (int x = 0; x < S; ++x) {
      const int sx = rotate180 ? x0 + S - 1 - x : x0 + x, sy = rotate180 ? y0 + S - 1 - y : y0 + y;
      const uint8_t* s = src.px(sx, sy);
      uint8_t* d = out.px(x, y);
      d[0] = s[0]; d[1] = s[1]; d[2] = s[2];
    }
  return out;
}

}  // namespace

CubeMapImages load_six_faces(const std::array<std::string, 6>& paths, int S) {
  CubeMapImages cm;
  cm.face_size = S;
  for (size_t f = 0; f < 6; ++f) {
    // The size from the header, before any pixel is read.
    cm.faces[f] = read_rgb8(paths[f], [&](int w, int h) {
      if (w != h) throw InputError(paths[f], "size", "face is " + size_str(w, h) + "; cube faces must be square");
      if (w != S)
        throw InputError(paths[f], "size", "face is " + size_str(w, h) + " but the display memory's faces are " +
                                               size_str(S, S) + " (memory.face_size)");
    });
  }
  return cm;
}

std::array<std::string, 6> six_face_paths_in(const std::string& folder) {
  static const char* stems[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError(folder, "", "is not a folder");
  std::array<std::string, 6> out;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    for (size_t f = 0; f < 6; ++f)
      if (entry.path().stem() == stems[f]) {
        if (!out[f].empty())
          throw InputError(folder, stems[f], "two files for the same face: " + out[f] + " and " + entry.path().string());
        out[f] = entry.path().string();
      }
  }
  for (size_t f = 0; f < 6; ++f)
    if (out[f].empty())
      throw InputError(folder, stems[f], "no face image named " + std::string(stems[f]) + ".<ext> (faces px nx py ny pz nz)");
  return out;
}

CubeMapImages load_cross(const std::string& path, int S) {
  // The layout from the header: 4:3 (horizontal) or 3:4 (vertical), 4 or 3 faces wide.
  const RgbImage img = read_rgb8(path, [&](int w, int h) {
    if (int64_t{w} * 3 == int64_t{h} * 4) {
      if (w != 4 * S)
        throw InputError(path, "size", "horizontal cross is " + size_str(w, h) + "; with faces of " + size_str(S, S) +
                                           " (memory.face_size) it must be " + size_str(4 * S, 3 * S));
    } else if (int64_t{w} * 4 == int64_t{h} * 3) {
      if (w != 3 * S)
        throw InputError(path, "size", "vertical cross is " + size_str(w, h) + "; with faces of " + size_str(S, S) +
                                           " (memory.face_size) it must be " + size_str(3 * S, 4 * S));
    } else {
      throw InputError(path, "size", "image is " + size_str(w, h) + "; a cross must be 4:3 (horizontal) or 3:4 (vertical)");
    }
  });
  CubeMapImages cm;
  cm.face_size = S;
  if (img.width * 3 == img.height * 4) {
    // cells (column, row): +X (2,1) -X (0,1) +Y (1,0) -Y (1,2) +Z (3,1) -Z (1,1)
    const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {3, 1}, {1, 1}};
    for (size_t f = 0; f < 6; ++f) cm.faces[f] = crop(img, cells[f][0] * S, cells[f][1] * S, S, false);
  } else {
    const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 3}, {1, 1}};
    for (size_t f = 0; f < 6; ++f) cm.faces[f] = crop(img, cells[f][0] * S, cells[f][1] * S, S, f == 4);
  }
  return cm;
}

CubeMapImages load_equirect(const std::string& path, int S) {
  const RgbImage img = read_rgb8(path, [&](int w, int h) {
    if (int64_t{w} != 2 * int64_t{h})
      throw InputError(path, "size", "panorama is " + size_str(w, h) + "; an equirectangular panorama must be 2:1");
  });
  CubeMapImages cm;
  cm.face_size = S;
  const auto& bases = face_bases();
  for (size_t f = 0; f < 6; ++f) {
    RgbImage face(S, S);
    const FaceBasis& b = bases[f];
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        // Inside-view pixel -> direction -> longitude/latitude -> panorama (bilinear, wrapping in longitude).
        const double a = 2.0 * (x + 0.5) / S - 1.0, c = 1.0 - 2.0 * (y + 0.5) / S;
        double d[3] = {b.forward.x + a * b.right.x + c * b.up.x, b.forward.y + a * b.right.y + c * b.up.y,
                       b.forward.z + a * b.right.z + c * b.up.z};
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double lon = std::atan2(d[0], -d[2]), lat = std::asin(std::clamp(d[1] / n, -1.0, 1.0));
        const double u = (0.5 + lon / (2 * kPi)) * img.width - 0.5, v = (0.5 - lat / kPi) * img.height - 0.5;
        const int u0 = static_cast<int>(std::floor(u)), v0 = static_cast<int>(std::floor(v));
        const double fu = u - u0, fv = v - v0;
        auto at = [&](int uu, int vv, int ch) {
          uu = ((uu % img.width) + img.width) % img.width;
          vv = std::clamp(vv, 0, img.height - 1);
          return static_cast<double>(img.px(uu, vv)[ch]);
        };
        for (int ch = 0; ch < 3; ++ch) {
          const double val = (1 - fv) * ((1 - fu) * at(u0, v0, ch) + fu * at(u0 + 1, v0, ch)) +
                             fv * ((1 - fu) * at(u0, v0 + 1, ch) + fu * at(u0 + 1, v0 + 1, ch));
          face.px(x, y)[ch] = static_cast<uint8_t>(std::clamp(std::lround(val), 0L, 255L));
        }
      }
    cm.faces[f] = std::move(face);
  }
  return cm;
}

}  // namespace arp::host
