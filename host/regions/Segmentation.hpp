// Large-object segmentation (Chow 2005), precomputed at load: every static
// object's mesh, in world space, is cut along the region boundary planes so
// each piece lies in one region and can go to that region's memory. A
// triangle crossing a plane is split exactly: the new vertex on an edge is
// computed from the edge's two ends in a fixed order (whichever end has the
// smaller coordinate tuple first), so the pieces on both sides share
// bit-identical boundary vertices -- no cracks (tested). Animated objects are
// not cut (they move between regions); an uncut object goes to the fastest
// memory among the regions its bound reaches.
#pragma once
#include <cstdint>
#include <vector>

#include "RegionGrid.hpp"
#include "host/scene/Scene.hpp"

namespace arp::host {

struct Segmented {
  Scene scene;                     // the pieces, as objects (static ones in world space)
  std::vector<int> region;         // flat region of each object of `scene` (of its centre, for uncut objects)
  // The regions each object's bound overlaps, as a box of region indices: an
  // uncut object spanning regions must be right everywhere it reaches, so it
  // goes to the fastest memory among them.
  std::vector<std::pair<RegionIndex, RegionIndex>> span;
  std::vector<size_t> source;      // the original object of each piece
  int64_t objects_cut = 0;         // originals that spanned more than one region
  int64_t segments = 0;            // pieces made from those
};

// `on` = false: no cutting; each object goes to the region of its centre.
Segmented segment_scene(const Scene& s, const RegionGrid& grid, bool on);

}  // namespace arp::host
