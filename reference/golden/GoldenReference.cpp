#include "GoldenReference.hpp"

#include <algorithm>
#include <cmath>

namespace arp::golden {

glm::dvec3 lens_direction(const dp::ArpConfig& c, int eye, int x, int y) {
  const double W = c.timing.h_active, H = c.timing.v_active;
  const double nose = c.timing.eyes == 2 ? (eye == 0 ? 1.0 : -1.0) : 0.0;
  const glm::dvec2 centre(W / 2.0 + nose * c.lens.center_offset_px, H / 2.0);
  const glm::dvec2 n = (glm::dvec2(x + 0.5, y + 0.5) - centre) / (W / 2.0);
  const double r2 = glm::dot(n, n);
  const auto& k = c.lens.k;
  const double scale = k[0] + k[1] * r2 + k[2] * r2 * r2 + k[3] * r2 * r2 * r2;
  const double t = std::tan(glm::radians(c.lens.fov_deg) / 2.0);
  return glm::normalize(glm::dvec3(n.x * scale * t, -n.y * scale * t, -1.0));
}

glm::dmat3 rotation(const glm::dquat& q) { return glm::mat3_cast(glm::normalize(q)); }

namespace {
// sc, tc, ma of the OpenGL cube-map table for each face.
void face_coords(const glm::dvec3& d, int face, double& sc, double& tc, double& ma) {
  switch (face) {
    case 0: sc = -d.z; tc = -d.y; ma = d.x; break;
    case 1: sc = d.z; tc = -d.y; ma = -d.x; break;
    case 2: sc = d.x; tc = d.z; ma = d.y; break;
    case 3: sc = d.x; tc = -d.z; ma = -d.y; break;
    case 4: sc = d.x; tc = -d.y; ma = d.z; break;
    default: sc = -d.x; tc = -d.y; ma = -d.z; break;
  }
}
}  // namespace

Address address(const glm::dvec3& d, int S) {
  const glm::dvec3 a = glm::abs(d);
  int face;
  if (a.x >= a.y && a.x >= a.z) face = d.x >= 0.0 ? 0 : 1;  // ties: X over Y over Z
  else if (a.y >= a.z) face = d.y >= 0.0 ? 2 : 3;
  else face = d.z >= 0.0 ? 4 : 5;
  double sc, tc, ma;
  face_coords(d, face, sc, tc, ma);
  Address r;
  r.face = face;
  r.u = (sc / ma + 1.0) / 2.0 * S;
  r.v = (tc / ma + 1.0) / 2.0 * S;
  r.x = std::clamp(static_cast<int>(std::floor(r.u)), 0, S - 1);
  r.y = std::clamp(static_cast<int>(std::floor(r.v)), 0, S - 1);
  return r;
}

bool project_onto_face(const glm::dvec3& d, int face, int S, double& u, double& v) {
  double sc, tc, ma;
  face_coords(d, face, sc, tc, ma);
  if (!(ma > 0.0)) return false;
  u = (sc / ma + 1.0) / 2.0 * S;
  v = (tc / ma + 1.0) / 2.0 * S;
  return true;
}

namespace {
struct Decoder {
  int bits[3], shift[3];
  double to_display[3];
  uint32_t empty;
  glm::dvec3 background;
  explicit Decoder(const dp::ArpConfig& c) {
    const auto& m = c.memory;
    bits[0] = m.red_bits; bits[1] = m.green_bits; bits[2] = m.blue_bits;
    shift[0] = m.green_bits + m.blue_bits; shift[1] = m.blue_bits; shift[2] = 0;
    const double dmax = std::ldexp(1.0, c.pipeline.display_bits) - 1.0;
    for (int i = 0; i < 3; ++i) {
      const double cmax = std::ldexp(1.0, bits[i]) - 1.0;
      to_display[i] = dmax / cmax;
      // background: RGB8 rounded to the memory's code, then to display units
      background[i] = std::floor(m.background[static_cast<size_t>(i)] * cmax / 255.0 + 0.5) * to_display[i];
    }
    empty = static_cast<uint32_t>(std::ldexp(1.0, m.depth_bits) - 1.0);
  }
  glm::dvec3 color(uint64_t word) const {
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i)
      c[i] = static_cast<double>((word >> shift[i]) & ((uint64_t{1} << bits[i]) - 1)) * to_display[i];
    return c;
  }
};

glm::dvec3 composite(const Decoder& dec, const dp::DisplayMemorySet& mem, int eye, int face, int x, int y) {
  uint32_t best_depth = dec.empty;
  uint64_t best = 0;
  for (int m = 0; m < mem.count(); ++m) {  // ascending: a tie keeps the lower memory index
    const uint64_t w = mem.bank(eye, m).read(face, x, y);
    const auto depth = static_cast<uint32_t>(w >> 32);
    if (depth < best_depth) { best_depth = depth; best = w; }
  }
  return best_depth == dec.empty ? dec.background : dec.color(best);
}
}  // namespace

glm::dvec3 sample(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem, int eye, const Address& a, bool bilinear) {
  const Decoder dec(c);
  const int S = c.memory.face_size;
  if (!bilinear) return composite(dec, mem, eye, a.face, a.x, a.y);
  const double us = a.u - 0.5, vs = a.v - 0.5;
  const int i0 = static_cast<int>(std::floor(us)), j0 = static_cast<int>(std::floor(vs));
  const double fx = us - i0, fy = vs - j0;
  auto cl = [S](int i) { return std::clamp(i, 0, S - 1); };
  const glm::dvec3 c00 = composite(dec, mem, eye, a.face, cl(i0), cl(j0));
  const glm::dvec3 c10 = composite(dec, mem, eye, a.face, cl(i0 + 1), cl(j0));
  const glm::dvec3 c01 = composite(dec, mem, eye, a.face, cl(i0), cl(j0 + 1));
  const glm::dvec3 c11 = composite(dec, mem, eye, a.face, cl(i0 + 1), cl(j0 + 1));
  return glm::mix(glm::mix(c00, c10, fx), glm::mix(c01, c11, fx), fy);
}

std::vector<glm::dvec3> frame(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem, const glm::dquat& q) {
  const int W = c.timing.h_active, H = c.timing.v_active, E = c.timing.eyes;
  const glm::dmat3 R = rotation(q);
  const bool bil = c.pipeline.aa == dp::AaMode::Bilinear;
  std::vector<glm::dvec3> out(static_cast<size_t>(E) * W * H);
#pragma omp parallel for schedule(dynamic, 8)
  for (int line = 0; line < E * H; ++line) {
    const int e = line / H, y = line % H;
    for (int x = 0; x < W; ++x)
      out[(static_cast<size_t>(e) * H + y) * W + x] =
          sample(c, mem, e, address(R * lens_direction(c, e, x, y), c.memory.face_size), bil);
  }
  return out;
}

}  // namespace arp::golden
