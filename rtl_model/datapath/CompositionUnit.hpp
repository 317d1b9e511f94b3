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

// Whether input word w, later in memory order, replaces `best`: strict, so ties keep the lower index.
inline bool nearer_than(uint64_t w, uint64_t best) { return texel_depth(w) < texel_depth(best); }

inline Composite composite_of(uint64_t best, int who, const CompositionParams& p) {
  const bool empty = texel_depth(best) == p.empty_depth;
  return {empty ? p.background : texel_color(best), texel_depth(best), empty ? -1 : who};
}

inline Composite compose(const uint64_t* words, int n, const CompositionParams& p) {
  uint64_t best = words[0];
  int who = 0;
#pragma GCC unroll 16  // n known where it is inlined: straight selects, so callers' pixel loops vectorise
  for (int i = 1; i < n; ++i) {
    const bool nearer = nearer_than(words[i], best);
    best = nearer ? words[i] : best;
    who = nearer ? i : who;
  }
  return composite_of(best, who, p);
}

// The same composite when only the inputs in `held` (bit i: input i) were read, every other one
// being known empty (a face never written: its depth code is the largest, so under the strict
// compare it never wins, and where all are empty the background shows either way). The words of
// the inputs not held are not looked at.
inline Composite compose_held(const uint64_t* words, uint32_t held, const CompositionParams& p) {
  uint64_t best = uint64_t{p.empty_depth} << 32;
  int who = 0;
  for (uint32_t b = held; b != 0; b &= b - 1) {
    const int i = __builtin_ctz(b);
    const bool nearer = nearer_than(words[i], best);
    best = nearer ? words[i] : best;
    who = nearer ? i : who;
  }
  return composite_of(best, who, p);
}

}  // namespace arp::dp
