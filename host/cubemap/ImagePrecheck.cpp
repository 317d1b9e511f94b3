#include "ImagePrecheck.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <vector>

#include "common/InputError.hpp"

namespace arp::host {

namespace {

uint32_t le32(const uint8_t* p) { return p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<uint32_t>(p[3]) << 24); }

// The header's width x height against the pixel limit (a power of two), at `place`.
void check_pixels(const std::string& path, const std::string& place, uint64_t w, uint64_t h, uint64_t max_pixels) {
  if (w * h <= max_pixels) return;
  int bits = 0;
  while ((uint64_t{1} << bits) < max_pixels) ++bits;
  throw InputError(path, place, "declares " + std::to_string(w) + " x " + std::to_string(h) + " pixels; images are limited to 2^" +
                                    std::to_string(bits) + " pixels");
}

// Scan lines per chunk for each OpenEXR compression (the file format's table).
int exr_lines_per_chunk(uint8_t compression) {
  switch (compression) {
    case 0: case 1: case 2: return 1;    // none, RLE, ZIPS
    case 3: case 5: return 16;           // ZIP, PXR24
    case 4: case 6: case 7: case 8: return 32;  // PIZ, B44, B44A, DWAA
    case 9: return 256;                  // DWAB
    default: return 0;                   // unknown
  }
}

void precheck_exr(const std::string& path, const std::vector<uint8_t>& h, uint64_t file_size, uint64_t max_pixels) {
  const uint32_t version = le32(&h[4]);
  if ((version & 0xff) != 2) throw InputError(path, "header", "OpenEXR version " + std::to_string(version & 0xff) + ", not 2");
  if (version & 0x1800) throw InputError(path, "header", "multi-part or deep OpenEXR: arpsim reads single-part, flat images");
  const bool tiled = version & 0x200;
  // Attributes: name\0 type\0 int32 size, value; an empty name ends the header.
  size_t p = 8;
  bool have_window = false;
  int32_t box[4] = {0, 0, 0, 0};
  int lines = 1;
  uint32_t tile_w = 0, tile_h = 0;
  for (;;) {
    auto cstr = [&](const char* what) {
      const auto end = std::find(h.begin() + static_cast<std::ptrdiff_t>(p), h.end(), uint8_t{0});
      if (end == h.end() || end - h.begin() - static_cast<std::ptrdiff_t>(p) > 255)
        throw InputError(path, "header", std::string("truncated or malformed OpenEXR header (") + what + ")");
      std::string s(h.begin() + static_cast<std::ptrdiff_t>(p), end);
      p = static_cast<size_t>(end - h.begin()) + 1;
      return s;
    };
    const std::string name = cstr("attribute name");
    if (name.empty()) break;
    const std::string type = cstr("attribute type");
    if (p + 4 > h.size()) throw InputError(path, "header", "truncated OpenEXR header (attribute size)");
    const uint32_t size = le32(&h[p]);
    p += 4;
    if (size > h.size() - p) throw InputError(path, "header", "OpenEXR attribute '" + quoted(name) + "' runs past the end of the file");
    const uint8_t* v = &h[p];
    if (name == "dataWindow" && type == "box2i" && size == 16) {
      for (int k = 0; k < 4; ++k) box[k] = static_cast<int32_t>(le32(v + 4 * k));
      have_window = true;
    } else if (name == "compression" && type == "compression" && size == 1) {
      lines = exr_lines_per_chunk(v[0]);
      if (lines == 0) throw InputError(path, "header", "unknown OpenEXR compression " + std::to_string(v[0]));
    } else if (name == "tiles" && type == "tiledesc" && size == 9) {
      tile_w = le32(v);
      tile_h = le32(v + 4);
    }
    p += size;
  }
  if (!have_window) throw InputError(path, "header", "OpenEXR header without a dataWindow");
  const int64_t w = int64_t{box[2]} - box[0] + 1, hgt = int64_t{box[3]} - box[1] + 1;
  if (w <= 0 || hgt <= 0) throw InputError(path, "dataWindow", "an empty or inverted data window");
  check_pixels(path, "dataWindow", static_cast<uint64_t>(w), static_cast<uint64_t>(hgt), max_pixels);
  // The offset table follows the header: one 8-byte offset a chunk (the first level's, for tiles).
  if (tiled && (tile_w == 0 || tile_h == 0)) throw InputError(path, "tiles", "a tiled OpenEXR file without a tile size");
  const uint64_t chunks = tiled ? static_cast<uint64_t>((w + tile_w - 1) / tile_w) * static_cast<uint64_t>((hgt + tile_h - 1) / tile_h)
                                : static_cast<uint64_t>((hgt + lines - 1) / lines);
  if (chunks * 8 > file_size - p)
    throw InputError(path, "dataWindow", std::to_string(w) + " x " + std::to_string(hgt) + " needs " + std::to_string(chunks) +
                                             " chunk offsets, " + std::to_string(chunks * 8) + " bytes, and the file has " +
                                             std::to_string(file_size - p) + " after its header: truncated, or not what it declares");
}

uint32_t be32(const uint8_t* p) { return (static_cast<uint32_t>(p[0]) << 24) | (p[1] << 16) | (p[2] << 8) | p[3]; }

// Every chunk's declared length within the file, up to IEND: libpng allocates
// a chunk it does not know by its declared length before reading it.
void precheck_png(const std::string& path, std::ifstream& in, uint64_t file_size, uint64_t max_pixels) {
  uint64_t at = 8;  // after the signature
  for (int n = 0;; ++n) {
    uint8_t head[8];
    in.seekg(static_cast<std::streamoff>(at));
    if (at + 8 > file_size || !in.read(reinterpret_cast<char*>(head), 8))
      throw InputError(path, "chunk " + std::to_string(n), "the file ends before its PNG chunks do (no IEND)");
    const uint32_t length = be32(head);
    const std::string type(reinterpret_cast<const char*>(head + 4), 4);
    const bool letters = std::all_of(type.begin(), type.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
    const std::string name = letters ? type : "not a chunk type";
    if (length > 0x7fffffffu || uint64_t{length} + 12 > file_size - at)
      throw InputError(path, "chunk " + std::to_string(n) + " (" + name + ")",
                       "declares " + std::to_string(length) + " bytes and the file has " + std::to_string(file_size - at - 8) +
                           " after its header: truncated, or not what it declares");
    if (n == 0 && type == "IHDR" && length >= 8) {
      if (!in.read(reinterpret_cast<char*>(head), 8)) throw InputError(path, "IHDR", "truncated");
      const uint64_t w = be32(head), h = be32(head + 4);
      check_pixels(path, "IHDR", w, h, max_pixels);
    }
    if (type == "IEND") return;
    at += uint64_t{length} + 12;
  }
}

uint16_t le16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }

// The info header's fields against each other: OpenImageIO's BMP reader
// trusts them (a 24-bit image marked run-length-8 crashed it).
void precheck_bmp(const std::string& path, std::ifstream& in, uint64_t file_size, uint64_t max_pixels) {
  uint8_t h[34] = {};
  in.clear();
  in.seekg(0);
  if (file_size < 26 || !in.read(reinterpret_cast<char*>(h), static_cast<std::streamsize>(std::min<uint64_t>(file_size, 34))))
    throw InputError(path, "header", "truncated BMP file");
  const uint32_t offset = le32(h + 10), info = le32(h + 14);
  int64_t w = 0, hgt = 0;
  uint16_t planes = 0, bpp = 0;
  uint32_t compression = 0;
  if (info == 12) {  // OS/2 core header: 16-bit sizes, no compression
    w = le16(h + 18);
    hgt = le16(h + 20);
    planes = le16(h + 22);
    bpp = le16(h + 24);
  } else if (info >= 40 && file_size >= 34) {
    w = static_cast<int32_t>(le32(h + 18));
    hgt = static_cast<int32_t>(le32(h + 22));  // negative: rows top-down
    planes = le16(h + 26);
    bpp = le16(h + 28);
    compression = le32(h + 30);
  } else {
    throw InputError(path, "header", "BMP info header of " + std::to_string(info) + " bytes (12, or 40 and more)");
  }
  if (hgt < 0) hgt = -hgt;
  if (w <= 0 || hgt <= 0) throw InputError(path, "header", "BMP of " + std::to_string(w) + " x " + std::to_string(hgt) + " pixels");
  check_pixels(path, "header", static_cast<uint64_t>(w), static_cast<uint64_t>(hgt), max_pixels);
  if (planes != 1) throw InputError(path, "header", "BMP with " + std::to_string(planes) + " planes (must be 1)");
  const bool depth_ok = compression == 0   ? (bpp == 1 || bpp == 4 || bpp == 8 || bpp == 16 || bpp == 24 || bpp == 32)
                        : compression == 1 ? bpp == 8    // RLE8
                        : compression == 2 ? bpp == 4    // RLE4
                        : compression == 3 ? (bpp == 16 || bpp == 32)  // bit fields
                                           : false;
  if (!depth_ok)
    throw InputError(path, "header", "BMP compression " + std::to_string(compression) + " with " + std::to_string(bpp) +
                                         " bits a pixel: not a combination the format has (0: 1-32 bits, 1: 8, 2: 4, 3: 16 or 32)");
  if (offset >= file_size) throw InputError(path, "header", "BMP pixel data offset " + std::to_string(offset) + " is past the end of the file");
}

// Netpbm (P1-P6) and PFM (PF, Pf): width, height and maxval (a PFM's scale) are text between blanks and '#'
// comments (a comment may touch a number); one blank ends the header of a binary file, whose pixel data's size
// the header then fixes. OpenImageIO's reader took a maxval of 0 (every sample divided by it) or above 65535,
// and sized the image from the header alone: a 1 KB file declaring 23168 x 11584 pixels took 930 MB.
void precheck_pnm(const std::string& path, std::ifstream& in, uint64_t file_size, uint64_t max_pixels) {
  const char kind = static_cast<char>(in.get());
  const bool pfm = kind == 'F' || kind == 'f', bitmap = kind == '1' || kind == '4';
  uint64_t field[3] = {0, 0, 1};
  static const char* const kName[3] = {"width", "height", "maxval"};
  const int fields = pfm || bitmap ? 2 : 3;  // (a PFM's scale, a real number, is left to its reader)
  const std::string format = pfm ? "PFM" : "PNM";
  constexpr int kEnd = std::char_traits<char>::eof();
  int c = in.get();
  for (int f = 0; f < fields; ++f) {
    while (c == '#' || std::isspace(c)) {
      if (c == '#')
        while (c != '\n' && c != '\r' && c != kEnd) c = in.get();
      else
        c = in.get();
    }
    if (!std::isdigit(c)) throw InputError(path, "header", format + " " + kName[f] + " is not a number");
    uint64_t v = 0;
    for (; std::isdigit(c); c = in.get())
      if ((v = v * 10 + static_cast<uint64_t>(c - '0')) > uint64_t{0x7fffffff})
        throw InputError(path, "header", format + " " + kName[f] + " beyond 2^31 - 1");
    field[f] = v;
  }
  if (field[0] == 0 || field[1] == 0)
    throw InputError(path, "header", format + " of " + std::to_string(field[0]) + " x " + std::to_string(field[1]) + " pixels");
  check_pixels(path, "header", field[0], field[1], max_pixels);
  if (field[2] < 1 || field[2] > 65535) throw InputError(path, "header", "PNM maxval " + std::to_string(field[2]) + " (must be 1 .. 65535)");
  if (kind == '1' || kind == '2' || kind == '3') return;  // plain (text) samples: no fixed size
  if (pfm) {  // the scale: a real number, read as a word
    while (std::isspace(c)) c = in.get();
    if (c == kEnd) throw InputError(path, "header", "PFM file ends before its scale");
    while (c != kEnd && !std::isspace(c)) c = in.get();
  }
  if (c == kEnd) throw InputError(path, "header", format + " file ends in its header: no pixel data");
  if (!std::isspace(c))
    throw InputError(path, "header", format + " header not ended by one blank" +
                                         std::string(c == '#' ? " (a comment there, which the readers do not take)" : ""));
  const uint64_t bytes = field[2] > 255 ? 2 : 1;
  const uint64_t row = kind == '4' ? (field[0] + 7) / 8 : field[0] * (kind == '5' ? bytes : kind == '6' ? 3 * bytes : kind == 'F' ? 12 : 4);
  const uint64_t header = static_cast<uint64_t>(in.tellg());
  const uint64_t need = row * field[1];  // (no overflow: width x height <= the pixel limit, checked above)
  if (in.fail() || header > file_size || file_size - header < need)
    throw InputError(path, "pixels", "the header declares " + std::to_string(field[0]) + " x " + std::to_string(field[1]) + " pixels, " +
                                         std::to_string(need) + " bytes; the file holds " +
                                         std::to_string(file_size - std::min(header, file_size)) + " after it");
}

}  // namespace

void precheck_image(const std::string& path, uint64_t file_size, uint64_t max_pixels) {
  static constexpr uint8_t kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  static constexpr uint8_t kPngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::ifstream in(path, std::ios::binary);
  uint8_t magic[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  in.read(reinterpret_cast<char*>(magic), 8);
  if (file_size >= 8 && std::memcmp(magic, kPngMagic, 8) == 0) return precheck_png(path, in, file_size, max_pixels);
  if (file_size >= 2 && magic[0] == 'B' && magic[1] == 'M') return precheck_bmp(path, in, file_size, max_pixels);
  if (file_size >= 2 && magic[0] == 'P' && ((magic[1] >= '1' && magic[1] <= '6') || magic[1] == 'F' || magic[1] == 'f')) {
    in.clear();
    in.seekg(1);
    return precheck_pnm(path, in, file_size, max_pixels);
  }
  if (file_size < 4 || std::memcmp(magic, kExrMagic, 4) != 0) return;  // neither: its decoder checks it
  // The header, at most 1 MiB (an OpenEXR header is attributes: a few kB at most in practice).
  std::vector<uint8_t> h(static_cast<size_t>(std::min<uint64_t>(file_size, uint64_t{1} << 20)));
  in.clear();
  in.seekg(0);
  in.read(reinterpret_cast<char*>(h.data()), static_cast<std::streamsize>(h.size()));
  if (h.size() < 8) throw InputError(path, "header", "truncated OpenEXR file");
  precheck_exr(path, h, file_size, max_pixels);
}

}  // namespace arp::host
