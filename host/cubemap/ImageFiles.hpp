// Image files through OpenImageIO: reading any format it knows into RGB8, and
// writing atomically (a temporary file in the same folder, then a rename), so
// a failed run never leaves a half-written image.
#pragma once
#include <filesystem>
#include <functional>
#include <cstdint>
#include <string>

#include "CubeMapImages.hpp"

namespace arp::host {

// What one input image may take: its pixels, and the bytes reading them needs
// (width x height x channels, 4 bytes a value for floating-point images),
// checked against its header before anything is allocated.
constexpr uint64_t kMaxImagePixels = uint64_t{1} << 28;
constexpr uint64_t kMaxImageBytes = uint64_t{1} << 30;

// Any channel count: 1 (grey) is replicated, alpha and extra channels dropped.
// InputError naming the file on a missing, non-regular, too large, unreadable
// or corrupt image, or a floating-point one holding NaN or infinity.
// `check_size`, when given, sees the header's width and height before any
// pixel is read (a layout the caller cannot use is refused without reading
// a gigabyte first); it throws to refuse.
RgbImage read_rgb8(const std::string& path, const std::function<void(int width, int height)>& check_size = {});

// Format from the extension (.png, .exr, .tif, ...), through a temporary file renamed into place.
// InputError naming the file on failure, with the reason (a full disk, a file-size limit: never a
// truncated image left behind a success).
void write_rgb8(const std::string& path, const RgbImage& img);
// InputError naming the option when no image format is known for path's extension, before any work (writing
// found it only at the end); nothing for an empty path.
void check_image_output(const std::string& option, const std::string& path);
// The same written to `file` as it is (a temporary path an arp::OutputGroup staged), errors naming `shown`.
void write_rgb8_file(const std::filesystem::path& file, const RgbImage& img, const std::string& shown);

}  // namespace arp::host
