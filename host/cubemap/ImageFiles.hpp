// Image files through OpenImageIO: reading any format it knows into RGB8, and
// writing atomically (a temporary file in the same folder, then a rename), so
// a failed run never leaves a half-written image.
#pragma once
#include <string>

#include "CubeMapImages.hpp"

namespace arp::host {

// Any channel count: 1 (grey) is replicated, alpha and extra channels dropped.
// InputError naming the file on a missing, unreadable or corrupt image.
RgbImage read_rgb8(const std::string& path);

// Format from the extension (.png, .exr, .tif, ...). InputError naming the file on failure.
void write_rgb8(const std::string& path, const RgbImage& img);

}  // namespace arp::host
