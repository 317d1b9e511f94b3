// What an image file's header promises, checked before any decoder sees it,
// where a decoder would allocate from the header alone. OpenEXR reads a
// scan-line or tile offset table sized by the data window before it finds that
// the file ends: a 717-byte file declaring a tall data window took 2 GB
// (found by the image fuzzer). An OpenEXR header is parsed here (bounded by the
// file's size) and refused when its data window exceeds the image limits or its
// offset table cannot fit in the file; other formats pass through unchanged.
#pragma once
#include <cstdint>
#include <string>

namespace arp::host {

// InputError naming `path` and the header field when the file cannot be what it declares.
void precheck_image(const std::string& path, uint64_t file_size, uint64_t max_pixels);

}  // namespace arp::host
