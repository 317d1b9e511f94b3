// What an image file's header promises, checked before any decoder sees it,
// where a decoder would allocate from the header alone or trust it (each
// found by the image fuzzer):
// - OpenEXR reads a scan-line or tile offset table sized by the data window
//   before it finds that the file ends: a 717-byte file took 2 GB. Its header
//   is parsed here (bounded by the file's size) and refused when the data
//   window exceeds the image limits or the offset table cannot fit in the file.
// - libpng allocates a chunk it does not know by its declared length: a
//   345-byte PNG declaring a 1.7 GB chunk took 1.8 GB. Every chunk's length
//   is checked against the rest of the file, up to IEND, and IHDR's size
//   against the pixel limit.
// - OpenImageIO's BMP reader trusts the info header: a 340-byte 24-bit BMP
//   marked run-length-8 crashed it (SIGSEGV). Bits a pixel, compression and
//   planes are checked against the combinations the format has, the size
//   against the pixel limit, the data offset against the file.
// - Netpbm and PFM: a maxval of 0 or above 65535 was read, and a 1 KB file
//   declaring 23168 x 11584 pixels took 930 MB: width, height and maxval are
//   checked, the size against the pixel limit, a binary file's pixel data
//   against the file's size.
// Other formats pass through unchanged.
#pragma once
#include <cstdint>
#include <string>

namespace arp::host {

// InputError naming `path` and the header field when the file cannot be what it declares.
void precheck_image(const std::string& path, uint64_t file_size, uint64_t max_pixels);

}  // namespace arp::host
