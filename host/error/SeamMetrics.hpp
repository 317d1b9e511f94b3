// Tearing along segment boundaries (Chow, Pose & Regan 2005): the pieces of
// one cut object may be shown by display memories rendered at different
// times, so where they meet the seam can open (background or another object
// showing through) or the pieces can be misaligned against the truth.
// Measured on per-pixel object maps: which object each displayed pixel shows
// (through the pipeline's own addressing and composition) and which the
// ground truth shows there.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace arp::host {

// One object id per display pixel, [eye][y][x]; 0 = nothing, else object index + 1.
struct ObjectMap {
  int width = 0, height = 0, eyes = 0;
  std::vector<uint32_t> id;

  void resize(int w, int h, int e) {
    width = w; height = h; eyes = e;
    id.assign(static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(e), 0);
  }
  size_t index(int eye, int x, int y) const {
    return (static_cast<size_t>(eye) * static_cast<size_t>(height) + static_cast<size_t>(y)) * static_cast<size_t>(width) +
           static_cast<size_t>(x);
  }
};

// What the seams are made of, per object index of the displayed scene.
struct SeamPieces {
  std::vector<size_t> source;  // the uncut object each piece was cut from
  std::vector<int> memory;     // the display memory showing each piece now (-1: none)
};

// Per-pixel marks, bits.
enum SeamMark : uint8_t {
  kSeamZone = 1,  // within a pixel of where two pieces shown by different memories meet in the truth
  kTearMark = 2,  // in the seam zone, showing another object or nothing
  kCrackMark = 4  // a run of 1..3 pixels showing something else between two such pieces on screen
};

struct SeamMeasure {
  int64_t tear_pixels = 0;   // seam-zone pixels showing another (uncut) object or nothing
  int64_t gap_pixels = 0;    // of those, the ones showing nothing (the background)
  int64_t crack_pixels = 0;  // pixels in an opened seam on screen, each counted once
  std::vector<uint8_t> marks;  // SeamMark bits, same layout as the maps
};

// shown and truth must have the same size; every id must be 0 or index an
// object of `pieces` (std::invalid_argument otherwise -- a programming error).
SeamMeasure measure_seams(const ObjectMap& shown, const ObjectMap& truth, const SeamPieces& pieces);

}  // namespace arp::host
