#include "SeamMetrics.hpp"

#include <stdexcept>

namespace arp::host {

namespace {

constexpr size_t kNone = SIZE_MAX;

}  // namespace

SeamMeasure measure_seams(const ObjectMap& shown, const ObjectMap& truth, const SeamPieces& pieces) {
  if (shown.width != truth.width || shown.height != truth.height || shown.eyes != truth.eyes ||
      shown.id.size() != truth.id.size() || pieces.source.size() != pieces.memory.size())
    throw std::invalid_argument("measure_seams: maps of different sizes");
  const size_t objects = pieces.source.size();
  for (const auto* m : {&shown, &truth})
    for (uint32_t v : m->id)
      if (v > objects) throw std::invalid_argument("measure_seams: object id out of range");
  auto src = [&](uint32_t id) { return id == 0 ? kNone : pieces.source[id - 1]; };
  auto mem = [&](uint32_t id) { return id == 0 ? -1 : pieces.memory[id - 1]; };
  // Two pieces of one cut object, shown by different memories.
  auto seam_pair = [&](uint32_t a, uint32_t b) { return a && b && a != b && src(a) == src(b) && mem(a) != mem(b); };

  SeamMeasure r;
  r.marks.assign(shown.id.size(), 0);
  const int W = shown.width, H = shown.height;
  for (int e = 0; e < shown.eyes; ++e)
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const uint32_t t = truth.id[truth.index(e, x, y)];
        // The seam zone: a 3x3 neighbourhood of both sides of a truth seam.
        for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
          if (x + dx >= W || y + dy >= H || !seam_pair(t, truth.id[truth.index(e, x + dx, y + dy)])) continue;
          for (int oy = -1; oy <= 1 + dy; ++oy)
            for (int ox = -1; ox <= 1 + dx; ++ox) {
              const int xx = x + ox, yy = y + oy;
              if (xx >= 0 && yy >= 0 && xx < W && yy < H) r.marks[shown.index(e, xx, yy)] |= kSeamZone;
            }
        }
        // An opened seam on screen: from a piece, a run of 1..3 pixels showing
        // something else, then another piece of the same object from another
        // memory. Every pixel of the run is marked.
        const uint32_t piece = shown.id[shown.index(e, x, y)];
        if (piece == 0) continue;
        for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}})
          for (int len = 1; len <= 3; ++len) {
            const int bx = x + (len + 1) * dx, by = y + (len + 1) * dy;
            const int ix = x + len * dx, iy = y + len * dy;
            if (bx >= W || by >= H || src(shown.id[shown.index(e, ix, iy)]) == src(piece)) break;
            if (seam_pair(piece, shown.id[shown.index(e, bx, by)])) {
              for (int k = 1; k <= len; ++k) r.marks[shown.index(e, x + k * dx, y + k * dy)] |= kCrackMark;
              break;
            }
          }
      }
  for (size_t k = 0; k < r.marks.size(); ++k) {
    if (r.marks[k] & kCrackMark) ++r.crack_pixels;
    if (!(r.marks[k] & kSeamZone) || src(shown.id[k]) == src(truth.id[k])) continue;
    r.marks[k] |= kTearMark;
    ++r.tear_pixels;
    if (shown.id[k] == 0) ++r.gap_pixels;
  }
  return r;
}

}  // namespace arp::host
