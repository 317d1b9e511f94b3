// The C interface of arpsim's image module (libarp_oiio.so, built from
// OiioModule.cpp): the only code that touches OpenImageIO. OpenImageIO
// brings in some 260 shared libraries (codecs, DICOM, HEIF, OpenCV...);
// loaded by every arpsim process they cost a quarter of a second at each
// start. host/cubemap/ImageFiles loads the module on its first image instead
// and keeps every check and message on its side; this interface only moves
// pixels and OpenImageIO's own error text.
#pragma once
#include <cstddef>

// The image formats arpsim reads (cube maps, panoramas, textures): OpenImageIO's
// name of the reader, the extensions that name it (comma-separated), what docs and
// messages call it. No other reader of OpenImageIO's is given a file.
struct ArpImageFormat {
  const char* oiio_name;
  const char* extensions;
  const char* title;
};
inline constexpr ArpImageFormat kArpImageFormats[] = {
    {"png", "png", "PNG"},
    {"jpeg", "jpg,jpeg,jpe,jfif", "JPEG"},
    {"tiff", "tif,tiff", "TIFF"},
    {"openexr", "exr", "OpenEXR"},
    {"hdr", "hdr,rgbe", "Radiance HDR"},
    {"pnm", "ppm,pgm,pbm,pnm", "PNM"},
    {"bmp", "bmp,dib", "BMP"},
    {"targa", "tga", "Targa"},
};

extern "C" {

struct ArpOiioSpec {
  int width, height, nchannels, is_float;
};

// Opens an image of one of kArpImageFormats and reads its header; null if it cannot, with
// OpenImageIO's reason in err, or err empty when no reader of those formats recognises the file.
void* arp_oiio_open(const char* path, ArpOiioSpec* spec, char* err, size_t err_len);
// Reads every pixel as UINT8 (as_float 0) or FLOAT (1), nchannels values a pixel; 0 and the reason on failure.
int arp_oiio_read(void* image, int as_float, void* pixels, char* err, size_t err_len);
void arp_oiio_close(void* image);
// Writes width x height RGB8 pixels to path in the format its extension names. 0 on success; 1: no
// format for that extension; 2: writing failed. The reason in err.
int arp_oiio_write(const char* path, int width, int height, const unsigned char* rgb, char* err, size_t err_len);
// 1 when OpenImageIO has a writer for the format path's extension names, else 0 (nothing is opened or written).
int arp_oiio_can_write(const char* path);
}
