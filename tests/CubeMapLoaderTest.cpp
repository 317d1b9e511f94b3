#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "TestSupport.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/CubeFaceBasis.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "common/InputError.hpp"

using namespace arp;
using namespace arp::host;

namespace {
const char* kStems[6] = {"px", "nx", "py", "ny", "pz", "nz"};

void write_faces(const test::TempDir& d, const CubeMapImages& cm) {
  for (size_t f = 0; f < 6; ++f) write_rgb8(d.file(std::string(kStems[f]) + ".png"), cm.faces[f]);
}

bool same(const RgbImage& a, const RgbImage& b) { return a.width == b.width && a.height == b.height && a.rgb == b.rgb; }

// The message of the InputError fn throws ("input: no error" when it throws none).
std::string message_of(const std::function<void()>& fn) { return test::error_of(fn).what(); }
}  // namespace

TEST(CubeMapLoader, SixFacesRoundTripThroughPng) {
  test::TempDir d;
  const CubeMapImages cm = make_calibration_pattern(64);
  write_faces(d, cm);
  const CubeMapImages back = load_six_faces(six_face_paths_in(d.path()), 64);
  for (size_t f = 0; f < 6; ++f) EXPECT_TRUE(same(back.faces[f], cm.faces[f])) << f;
}

TEST(CubeMapLoader, HorizontalAndVerticalCrossesMatchTheFaces) {
  test::TempDir d;
  const int S = 32;
  const CubeMapImages cm = make_calibration_pattern(S);
  RgbImage h(4 * S, 3 * S), v(3 * S, 4 * S);
  const int hc[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {3, 1}, {1, 1}};
  const int vc[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 3}, {1, 1}};
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        const uint8_t* p = cm.faces[static_cast<size_t>(f)].px(x, y);
        std::copy(p, p + 3, h.px(hc[f][0] * S + x, hc[f][1] * S + y));
        const bool back = f == 4;  // the vertical cross holds the back face upside down
        std::copy(p, p + 3, v.px(vc[f][0] * S + (back ? S - 1 - x : x), vc[f][1] * S + (back ? S - 1 - y : y)));
      }
  write_rgb8(d.file("h.png"), h);
  write_rgb8(d.file("v.png"), v);
  const CubeMapImages a = load_cross(d.file("h.png"), S), b = load_cross(d.file("v.png"), S);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_TRUE(same(a.faces[f], cm.faces[f])) << f;
    EXPECT_TRUE(same(b.faces[f], cm.faces[f])) << f;
  }
}

TEST(CubeMapLoader, EquirectangularLongitudeZeroIsTheFrontAndUpIsUp) {
  test::TempDir d;
  // Colour by region: top band red, bottom band blue, otherwise green rising with longitude.
  RgbImage pano(256, 128);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x) {
      uint8_t* p = pano.px(x, y);
      p[0] = y < 20 ? 255 : 0;
      p[2] = y >= 108 ? 255 : 0;
      p[1] = (y >= 20 && y < 108) ? static_cast<uint8_t>(x) : 0;
    }
  write_rgb8(d.file("pano.png"), pano);
  const CubeMapImages cm = load_equirect(d.file("pano.png"), 32);
  auto centre = [&](int face) { return cm.faces[static_cast<size_t>(face)].px(16, 16); };
  EXPECT_EQ(centre(2)[0], 255);               // +Y: up
  EXPECT_EQ(centre(3)[2], 255);               // -Y: down
  EXPECT_NEAR(centre(5)[1], 128, 2);          // -Z front: longitude 0, the panorama's middle column
  EXPECT_NEAR(centre(0)[1], 128 + 64, 2);     // +X right: longitude +90
  EXPECT_NEAR(centre(1)[1], 128 - 64, 2);     // -X left: longitude -90
  // Left-to-right in the front face image runs with longitude.
  EXPECT_LT(cm.faces[5].px(2, 16)[1], cm.faces[5].px(29, 16)[1]);
}

TEST(DisplayMemoryFill, TexelMappingGoesThroughDirections) {
  const int S = 16;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        int col, row;
        memory_texel_to_image(f, x, y, S, col, row);
        ASSERT_GE(col, 0);
        ASSERT_LT(col, S);
        ASSERT_GE(row, 0);
        ASSERT_LT(row, S);
        // The image pixel's inside-view direction equals the memory texel's direction.
        const FaceBasis& b = face_bases()[static_cast<size_t>(f)];
        const double a = 2.0 * (col + 0.5) / S - 1.0, c = 1.0 - 2.0 * (row + 0.5) / S;
        const Dir3 img{b.forward.x + a * b.right.x + c * b.up.x, b.forward.y + a * b.right.y + c * b.up.y,
                       b.forward.z + a * b.right.z + c * b.up.z};
        const Dir3 mem = memory_texel_direction(f, x, y, S);
        ASSERT_NEAR(img.x, mem.x, 1e-12);
        ASSERT_NEAR(img.y, mem.y, 1e-12);
        ASSERT_NEAR(img.z, mem.z, 1e-12);
      }
}

TEST(CubeMapLoader, BadInputsNameTheFileAndTheReason) {
  test::TempDir d;
  const CubeMapImages cm = make_calibration_pattern(32);
  EXPECT_NE(message_of([&] { read_rgb8(d.file("missing.png")); }).find("does not exist"), std::string::npos);
  {
    std::ofstream(d.file("corrupt.png"), std::ios::binary) << "\x89PNG\r\n\x1a\n this is not a png body at all";
    const std::string e = message_of([&] { read_rgb8(d.file("corrupt.png")); });
    EXPECT_NE(e.find("corrupt.png"), std::string::npos) << e;
  }
  {
    std::ofstream(d.file("text.png")) << "hello";
    EXPECT_NE(message_of([&] { read_rgb8(d.file("text.png")); }).find("text.png"), std::string::npos);
  }
  write_faces(d, cm);
  EXPECT_NE(message_of([&] { load_six_faces(six_face_paths_in(d.path()), 64); }).find("memory.face_size"), std::string::npos);
  write_rgb8(d.file("px.png"), RgbImage(32, 16));
  EXPECT_NE(message_of([&] { load_six_faces(six_face_paths_in(d.path()), 32); }).find("must be square"), std::string::npos);
  std::filesystem::remove(d.file("nz.png"));
  EXPECT_NE(message_of([&] { six_face_paths_in(d.path()); }).find("nz"), std::string::npos);
  write_rgb8(d.file("wide.png"), RgbImage(100, 30));
  EXPECT_NE(message_of([&] { load_cross(d.file("wide.png"), 32); }).find("4:3"), std::string::npos);
  write_rgb8(d.file("cross.png"), RgbImage(4 * 20, 3 * 20));
  EXPECT_NE(message_of([&] { load_cross(d.file("cross.png"), 32); }).find("128x96"), std::string::npos);
  EXPECT_NE(message_of([&] { load_equirect(d.file("wide.png"), 32); }).find("2:1"), std::string::npos);
  EXPECT_NE(message_of([&] { six_face_paths_in(d.file("nope")); }).find("not a folder"), std::string::npos);
}

// Only the readers of the documented formats see a file, chosen by its content
// among them (its extension's first); a format OpenImageIO reads but arpsim does
// not document (here SGI, which OpenImageIO also writes) is refused, by either name.
TEST(ImageFiles, ReadsOnlyTheDocumentedFormatsWhateverTheName) {
  test::TempDir d;
  RgbImage img(6, 4);
  img.rgb[0] = 200;
  write_rgb8(d.file("a.jpg"), img);
  std::filesystem::copy_file(d.file("a.jpg"), d.file("jpeg-called.png"));
  std::filesystem::copy_file(d.file("a.jpg"), d.file("no-extension"));
  EXPECT_EQ(read_rgb8(d.file("jpeg-called.png")).width, 6);
  EXPECT_EQ(read_rgb8(d.file("no-extension")).height, 4);
  write_rgb8(d.file("b.sgi"), img);
  std::filesystem::copy_file(d.file("b.sgi"), d.file("sgi-called.png"));
  for (const char* name : {"b.sgi", "sgi-called.png"}) {
    const std::string e = message_of([&] { read_rgb8(d.file(name)); });
    EXPECT_NE(e.find(name), std::string::npos) << e;
    EXPECT_NE(e.find("not an image of a format arpsim reads (PNG, JPEG, TIFF, OpenEXR, Radiance HDR, PNM, BMP, Targa)"),
              std::string::npos)
        << e;
  }
}

// An OpenEXR header is checked before OpenEXR reads it: OpenEXR sizes its
// chunk offset table from the data window before it finds the file's end (a
// 717-byte file took 2 GB). A window the file cannot hold the table of, one
// beyond the pixel limit, or a header cut short is refused by name; a real
// file, scan-line or tiled, reads.
TEST(ImageFiles, AnOpenExrHeaderMustFitItsFile) {
  test::TempDir d;
  write_rgb8(d.file("a.exr"), RgbImage(8, 4));
  EXPECT_EQ(read_rgb8(d.file("a.exr")).width, 8);
  const std::string good = test::read_text(d.file("a.exr"));
  const std::string key = std::string("dataWindow") + '\0' + "box2i" + '\0';
  const size_t at = good.find(key);
  ASSERT_NE(at, std::string::npos);
  auto with_window = [&](const std::string& name, int32_t xmax, int32_t ymax) {
    std::string f = good;
    std::memcpy(&f[at + key.size() + 4 + 8], &xmax, 4);
    std::memcpy(&f[at + key.size() + 4 + 12], &ymax, 4);
    std::ofstream(d.file(name), std::ios::binary) << f;
    return test::error_of([&] { read_rgb8(d.file(name)); });
  };
  const InputError tall = with_window("tall.exr", 7, 99999);
  EXPECT_EQ(tall.place(), "dataWindow");
  EXPECT_NE(tall.reason().find("chunk offsets"), std::string::npos) << tall.what();
  const InputError huge = with_window("huge.exr", 29999, 29999);
  EXPECT_NE(huge.reason().find("30000 x 30000"), std::string::npos) << huge.what();
  std::ofstream(d.file("cut.exr"), std::ios::binary) << good.substr(0, 40);
  EXPECT_EQ(test::error_of([&] { read_rgb8(d.file("cut.exr")); }).place(), "header");
}

// Every PNG chunk's declared length is checked against the file before libpng
// reads it: libpng allocates an unknown chunk by its declared length (a
// 345-byte file took 1.8 GB). A chunk longer than the rest of the file, a file
// cut before IEND, or an IHDR beyond the pixel limit is refused by name.
TEST(ImageFiles, EveryPngChunkMustFitItsFile) {
  test::TempDir d;
  write_rgb8(d.file("a.png"), RgbImage(8, 4));
  EXPECT_EQ(read_rgb8(d.file("a.png")).width, 8);
  const std::string good = test::read_text(d.file("a.png"));
  ASSERT_EQ(good.substr(12, 4), "IHDR");
  auto refused = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(d.file(name), std::ios::binary) << bytes;
    return test::error_of([&] { read_rgb8(d.file(name)); });
  };
  // A private ancillary chunk of 1.6 GB declared, 4 bytes there, after IHDR (8 + 25 bytes).
  const InputError big = refused("big.png", good.substr(0, 33) + std::string("\x60\0\0\0prIv\0\0\0\0", 12) + good.substr(33));
  EXPECT_EQ(big.place(), "chunk 1 (prIv)");
  EXPECT_NE(big.reason().find("declares 1610612736 bytes"), std::string::npos) << big.what();
  EXPECT_NE(refused("cut.png", good.substr(0, good.size() - 12)).reason().find("no IEND"), std::string::npos);
  std::string wide = good;
  wide.replace(16, 8, std::string("\0\0\x75\x30\0\0\x75\x30", 8));  // 30000 x 30000
  EXPECT_EQ(refused("wide.png", wide).place(), "IHDR");
}

// A BMP's info header is checked before OpenImageIO's reader trusts it: a
// 24-bit image marked run-length-8 crashed it (SIGSEGV, found by the fuzzer).
TEST(ImageFiles, ABmpHeaderMustBeACombinationTheFormatHas) {
  test::TempDir d;
  write_rgb8(d.file("a.bmp"), RgbImage(8, 4));
  EXPECT_EQ(read_rgb8(d.file("a.bmp")).width, 8);
  std::string f = test::read_text(d.file("a.bmp"));
  ASSERT_EQ(f[28], 24);  // bits a pixel
  f[30] = 1;             // compression: run-length 8
  std::ofstream(d.file("rle.bmp"), std::ios::binary) << f;
  const InputError e = test::error_of([&] { read_rgb8(d.file("rle.bmp")); });
  EXPECT_EQ(e.place(), "header");
  EXPECT_NE(e.reason().find("compression 1 with 24 bits"), std::string::npos) << e.what();
}

// Netpbm and PFM headers are checked before OpenImageIO sizes an image from them: width, height, maxval
// and, for binary files, the pixel data the header fixes against the file's size. What the formats allow
// still reads: a comment touching a number, plain (text) samples, two bytes a sample, PFM floats.
TEST(ImageFiles, ANetpbmHeaderMustFitItsFile) {
  test::TempDir d;
  const auto file = [&](const std::string& name, const std::string& header, size_t data_bytes, char fill = '\x40') {
    std::ofstream(d.file(name), std::ios::binary) << header << std::string(data_bytes, fill);
    return d.file(name);
  };
  const std::vector<std::pair<std::string, std::string>> good = {
      {"a.ppm", "P6\n# made by hand\n8#width\n4 255\n"}, {"b.pgm", "P5 8 4#h\n255\n"}, {"c.ppm", "P6\r\n8 4\r\n65535\n"}};
  for (const auto& [name, header] : good) {
    const size_t bytes = 8 * 4 * (name[0] == 'a' ? 3 : name[0] == 'b' ? 1 : 6);
    EXPECT_EQ(read_rgb8(file(name, header, bytes)).width, 8) << name;
  }
  std::ofstream(d.file("plain.pgm")) << "P2\n# plain\n2 2#size\n255\n0 64\n128 255\n";
  EXPECT_EQ(read_rgb8(d.file("plain.pgm")).height, 2);
  for (const std::string header : {"PF\n8 4\n-1.0\n", "PF\n8 4\n-1.0 ", "PF\r8 4\r-1.0\r"})  // the scale ended by any blank
    EXPECT_EQ(read_rgb8(file("f.pfm", header, 8 * 4 * 12, '\0')).width, 8) << header;
  const std::vector<std::tuple<std::string, std::string, size_t, std::string>> bad = {
      {"short.ppm", "P6\n23168 11584\n255\n", 1000, "declares 23168 x 11584 pixels, 805134336 bytes; the file holds 1000 after it"},
      {"short.pfm", "PF\n11584 5792\n-1.0\n", 1000, "declares 11584 x 5792 pixels, 805134336 bytes"},
      {"short16.pgm", "P5 8 4 65535\n", 63, "64 bytes; the file holds 63"},
      {"wide.pbm", "P4\n4294967296 4294967296\n", 16, "PNM width beyond 2^31 - 1"},
      {"big.pgm", "P5\n65536 65536\n255\n", 16, "images are limited to 2^"},
      {"zero.pgm", "P5\n8 4\n0\n", 32, "PNM maxval 0 (must be 1 .. 65535)"},
      {"nonum.pgm", "P5\n8 x\n255\n", 32, "PNM height is not a number"},
      {"ends.ppm", "P6\n8 4\n255", 0, "PNM file ends in its header: no pixel data"},
      {"noscale.pfm", "PF\n8 4\n", 0, "PFM file ends before its scale"}};
  for (const auto& [name, header, bytes, says] : bad) {
    const InputError e = test::error_of([&] { read_rgb8(file(name, header, bytes)); });
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << name << ": " << e.what();
  }
}

TEST(ImageFiles, WritesAtomicallyAndRefusesUnknownFormats) {
  test::TempDir d;
  const size_t before = d.entries();
  EXPECT_THROW(write_rgb8(d.file("out.notaformat"), RgbImage(4, 4)), InputError);
  EXPECT_THROW(write_rgb8(d.file("no/such/folder/out.png"), RgbImage(4, 4)), InputError);
  EXPECT_EQ(d.entries(), before);  // nothing half-written left behind
  write_rgb8(d.file("ok.exr"), RgbImage(4, 4));
  EXPECT_EQ(d.entries(), before + 1);
  EXPECT_EQ(read_rgb8(d.file("ok.exr")).width, 4);
}

TEST(CalibrationPattern, FacesAreDistinctAndDeterministic) {
  const CubeMapImages a = make_calibration_pattern(128), b = make_calibration_pattern(128);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_TRUE(same(a.faces[f], b.faces[f]));
    for (size_t g = f + 1; g < 6; ++g) EXPECT_FALSE(same(a.faces[f], a.faces[g]));
  }
  // A label is not mirror-symmetric, so a flipped face would show.
  const RgbImage& front = a.faces[5];
  bool asymmetric = false;
  for (int y = 0; y < 128 && !asymmetric; ++y)
    for (int x = 0; x < 64 && !asymmetric; ++x) asymmetric = front.px(x, y)[0] != front.px(127 - x, y)[0];
  EXPECT_TRUE(asymmetric);
}
