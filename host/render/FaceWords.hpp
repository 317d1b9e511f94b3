// A drawn face's texels as display memory words: the depth code of each radial distance
// (DepthCode::codes), each colour clamped to 0 .. 1, rounded to 8 bits a channel (halves up) and packed
// in the memory's format (dp::Rgb8Packer); the memory's empty word where nothing was drawn (an infinite
// distance). The software renderer's store, in vectorised passes of a few hundred texels.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "DepthCode.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::host {

void face_words(const double* distance, const glm::dvec3* color, size_t n, const DepthCode& depth, const dp::Rgb8Packer& pack,
                uint64_t empty, uint64_t* out);

}  // namespace arp::host
