// Host -> display memory without a renderer: writes a cube map's six
// inside-view images into a bank's back buffer at one depth code (the
// texel-for-texel mapping goes through directions; see CubeFaceBasis.hpp) and commits.
#pragma once
#include <cstdint>

#include "CubeMapImages.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::host {

// The farthest non-empty depth code: a cube map at infinity.
inline uint32_t far_depth(const dp::MemoryFormat& f) { return f.empty_depth() - 1; }

// Maps display-memory texel (face, x, y) to the pixel of the inside-view image that holds it.
void memory_texel_to_image(int face, int x, int y, int S, int& col, int& row);

void fill_back_buffer(dp::DisplayMemoryBank& bank, const CubeMapImages& cm, uint32_t depth);

// Fills memory `memory` of every eye, commits and (optionally) swaps so the pipeline sees it now.
void load_into_memories(dp::DisplayMemorySet& set, int memory, const CubeMapImages& cm, uint32_t depth,
                        bool swap_now = true);

}  // namespace arp::host
