// Composition unit: of the texels fetched from the N display memories at one
// address, the nearest (smallest depth code) wins. Tie rule: the lower memory
// index wins -- memory 0 is the most frequently updated, so its image is the
// most recent. Where every memory is empty the background colour shows.
#pragma once
#include <cstdint>

#include "DisplayMemoryBank.hpp"

namespace arp::dp {

struct CompositionParams {
  uint32_t empty_depth;
  uint32_t background;  // in the memory's colour code
  CompositionParams(const MemoryFormat& f, const std::array<int, 3>& bg_rgb8)
      : empty_depth(f.empty_depth()), background(f.pack_rgb8(bg_rgb8[0], bg_rgb8[1], bg_rgb8[2])) {}
};

struct Composite {
  uint32_t color;
  uint32_t depth;
  int memory;  // winning memory, -1 for background
};

inline Composite compose(const uint64_t* words, int n, const CompositionParams& p) {
  uint64_t best = words[0];
  int who = 0;
#pragma GCC unroll 16  // n known where it is inlined: straight selects, so callers' pixel loops vectorise
  for (int i = 1; i < n; ++i) {
    const bool nearer = texel_depth(words[i]) < texel_depth(best);  // strict: ties keep the lower index
    best = nearer ? words[i] : best;
    who = nearer ? i : who;
  }
  const bool empty = texel_depth(best) == p.empty_depth;
  return {empty ? p.background : texel_color(best), texel_depth(best), empty ? -1 : who};
}

}  // namespace arp::dp
