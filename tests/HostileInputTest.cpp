// Issue 19's reproductions, each now a clear refusal: the file (or option),
// the place and the reason, exit status 2, at most a few lines on stderr,
// and nothing written. Generated
// inputs (deep nesting, huge headers, special files, long values) are built
// here; small fixed ones live in tests/data/hostile (see its README).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"

using arp::test::run_command;
using arp::test::TempDir;
namespace fs = std::filesystem;

namespace {

const std::string kArpsim = ARPSIM_BINARY;
const std::string kData = std::string(ARPSIM_SOURCE_DIR) + "/tests/data/hostile/";

struct Case {
  std::string args;  // after "arpsim "
  int status;        // 2: bad input (a file, a value, a malformed option)
  std::string says;  // part of the message
};

void expect_refused(const std::vector<Case>& cases, const TempDir& d) {
  for (const Case& c : cases) {
    const auto r = run_command("cd " + d.path() + " && timeout 120 " + kArpsim + " " + c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output.substr(0, 2000);
    EXPECT_LT(r.output.size(), 1200u) << c.args;  // a message, not a flood or an echo of the input
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_EQ(r.output.find("libpng"), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(d.file("out.png"))) << c.args;
    EXPECT_FALSE(fs::exists(d.file("r.json"))) << c.args;
  }
}

// A little-endian TIFF whose header declares width x height x channels of 8-bit samples and holds 16 bytes.
std::string tiff_header(uint32_t width, uint32_t height, uint16_t channels) {
  std::string t = std::string("II*\0", 4);
  auto u16 = [&](uint16_t v) { t.push_back(static_cast<char>(v & 0xff)), t.push_back(static_cast<char>(v >> 8)); };
  auto u32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) t.push_back(static_cast<char>((v >> (8 * i)) & 0xff)); };
  u32(8);  // the first directory
  const uint16_t entries = 9;
  u16(entries);
  auto entry = [&](uint16_t tag, uint16_t type, uint32_t value) {
    u16(tag), u16(type), u32(1), (type == 3 ? (u16(static_cast<uint16_t>(value)), u16(0)) : u32(value));
  };
  const uint32_t data = 8 + 2 + entries * 12 + 4;
  entry(256, 4, width);
  entry(257, 4, height);
  entry(258, 3, 8);          // bits per sample
  entry(259, 3, 1);          // no compression
  entry(262, 3, 1);          // min-is-black
  entry(273, 4, data);       // strip offset
  entry(277, 3, channels);   // samples per pixel
  entry(278, 4, height);     // rows per strip
  entry(279, 4, 16);         // strip bytes: far fewer than declared
  u32(0);
  t += std::string(16, '\x7f');
  return t;
}

}  // namespace

TEST(HostileInput, BadFilesAreRefusedWithFilePlaceAndReason) {
  TempDir d;
  // Generated: a JSON value nested 100 000 deep, a 10 MB value, a huge TIFF header, a FIFO.
  std::ofstream(d.file("deep.json")) << std::string(100000, '[') << std::string(100000, ']');
  std::ofstream(d.file("long.json")) << "{\"objects\": [{\"sphere\": \"" << std::string(10 << 20, 'x') << "\"}]}";
  std::ofstream(d.file("huge.tif"), std::ios::binary) << tiff_header(16384, 16384, 16);
  ASSERT_EQ(::mkfifo(d.file("fifo").c_str(), 0600), 0);
  const std::string H = kData;
  expect_refused(
      {
          // Model import: a hang and a 10^9-vertex header, through a scene.
          {"frame --out out.png --scene " + H + "scene-truncated-model.json", 2, "truncated.ply"},
          {"frame --out out.png --scene " + H + "scene-huge-model.json", 2, "declares 1000000000"},
          // Configuration: nesting, overflow, narrowing, duplicates, NUL bytes, huge integers.
          {"config --config deep.json", 2, "nested deeper than 64"},
          {"config --set lens.k=[1e400,0,0,0]", 2, "too large for a double"},
          {"config --set memory.background=[4294967296,0,0]", 2, "element 0 is 4294967296, must be in [0, 255]"},
          {"config --config " + H + "config-narrowing.json", 2, "element 0 is 4294967296"},
          {"config --config " + H + "config-duplicate.json", 2, "vec_frac"},
          {"config --config " + H + "config-nul.json", 2, "NUL byte"},
          {"config --set memory.face_size=18446744073709551615", 2, "must be in 1 .. 2^14"},
          {"config --set lens.k=[1e308,0,0,0]", 2, "must be in"},
          // Scenes and walks.
          {"frame --out out.png --scene " + H + "scene-fractional-segments.json", 2, "segments"},
          {"frame --out out.png --scene " + H + "scene-overflow.json", 2, "too large for a double"},
          {"frame --out out.png --scene long.json", 2, "sphere"},
          {"run -q --frames 1 --scene gallery --walk " + H + "walk-overflow.json --report r.json", 2, "too large for a double"},
          // Images: bytes counted from the header before anything is allocated; special files.
          {"frame --out out.png --cross huge.tif", 2, "images are limited to 1024 MB"},
          {"frame --out out.png --cross /dev/zero", 2, "must be a regular file"},
          {"frame --out out.png --cross fifo", 2, "must be a regular file"},
          {"config --config /dev/zero", 2, "must be a regular file"},
          {"config --config fifo", 2, "must be a regular file"},
          {"frame --out out.png --scene /dev/zero", 2, "must be a regular file"},
          {"run -q --frames 1 --scene gallery --walk /dev/zero --report r.json", 2, "must be a regular file"},
          {"run -q --frames 1 --trace /dev/zero --report r.json", 2, "must be a regular file"},
          {"run -q --frames 1 --trace fifo --report r.json", 2, "must be a regular file"},
          {"run -q --frames 1 --trace " + H + "trace-nul.csv --report r.json", 2, "line 3: a NUL byte"},
          {"gtkw /dev/zero -o x.gtkw", 2, "must be a regular file"},
          {"gtkw " + H + "bad-timestamp.vcd -o x.gtkw", 2, "line 6: '#abc' is not a timestamp"},
          {"tracker import /dev/zero t.csv", 2, "must be a regular file"},
      },
      d);
}

TEST(HostileInput, TimesOutsideThe64BitPicosecondRangeAreRefusedWithTheLimit) {
  TempDir d;
  expect_refused(
      {
          {"frame --out out.png --frame 1000000000000", 2, "past the last frame whose times fit"},
          {"frame --out out.png --frame 9223372036854775808", 2, "outside the range"},
          {"frame --out out.png --frame -1", 2, "--frame"},
          {"run -q --frames 1 --first-frame 1000000000 --report r.json", 2, "days at this display's 59.94 Hz"},
          // A 1 kHz pixel clock: 420 s a frame, so the range ends after about 21 960 frames.
          {"run -q --frames 1 --first-frame 30000 --set display.pixel_clock_hz=1000 --report r.json", 2, "past the last frame"},
          {"run -q --frames 1000000 --first-frame 552000000 --report r.json", 2, "past the last frame"},
      },
      d);
  // A run ending within a frame of the range's end: its motion window is held
  // at the range's end, not wrapped (UBSan aborts on the overflow in the ASan build).
  const auto last = run_command(kArpsim + " run -q --frames 1 --first-frame 552853308 --every 0 --report " + d.file("last.json"));
  EXPECT_EQ(last.status, 0) << last.output;
  // Inside the range, at its end: times are right, not wrapped.
  const auto r = run_command(kArpsim + " frame --out " + d.file("f.png") + " --frame 552853309 --report " + d.file("f.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(d.file("f.json"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("\"first_photon_ps\": ");
  ASSERT_NE(at, std::string::npos);
  const double first_ps = std::stod(text.substr(at + 19));
  EXPECT_NEAR(first_ps, 552853309.0 * 420000.0 / 25.175e6 * 1e12, 1e7);  // frame x frame time, closed form
}

TEST(HostileInput, NumericOptionsAreStrict) {
  TempDir d;
  expect_refused(
      {
          {"run -q --frames 0x10", 2, "'0x10' is not a whole number"},
          {"run -q --frames 1e3", 2, "not a whole number"},
          {"frame --out out.png --yaw 1e400", 2, "not a finite number"},
          {"frame --out out.png --yaw nan", 2, "not a finite number"},
          {"frame --out out.png --pitch inf", 2, "not a finite number"},
      },
      d);
  // "010" is ten, not octal eight; a denormal is a number.
  const auto r = run_command(kArpsim + " frame --out " + d.file("f.png") + " --frame 010 --yaw 1e-320");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("frame 10 at"), std::string::npos) << r.output;
}

TEST(HostileInput, OutputsAreCheckedBeforeAnythingRunsAndNeverOverwriteAnInput) {
  TempDir d;
  ASSERT_EQ(run_command(kArpsim + " frame --out " + d.file("x.png")).status, 0);
  ASSERT_EQ(run_command(kArpsim + " tracker synth --motion rotate --seconds 1 --out " + d.file("t.csv")).status, 0);
  std::ofstream(d.file("d.txt")) << "timestamp frameId w x y z\n0 0 1 0 0 0\n1 1 1 0 0 0\n";
  const auto size_of = [&](const std::string& f) { return fs::file_size(d.file(f)); };
  const auto png = size_of("x.png"), csv = size_of("t.csv"), txt = size_of("d.txt");
  expect_refused(
      {
          {"frame --cross x.png --out x.png", 2, "is the --cross input"},
          {"frame --cross x.png --out ./x.png", 2, "is the --cross input"},
          {"tracker import d.txt d.txt", 2, "is the dataset input"},
          {"run -q --frames 1 --trace t.csv --report t.csv", 2, "is the --trace input"},
          {"run -q --frames 1 --report r.json --csv r.json", 2, "is also the --report output"},
          {"run -q --frames 1 --report /proc/r.json", 2, "cannot write there"},
          {"run -q --frames 1 --report missing/r.json", 2, "does not exist"},
          {"run -q --frames 1 --report " + d.path(), 2, "is a folder"},
          // A valid report beside an unwritable host CSV: refused before the run, neither written.
          {"run -q --frames 1 --scene gallery --walk gallery --report r.json --host-csv /proc/h.csv", 2, "--host-csv"},
          {"latency --out-dir /proc/x", 2, "cannot create the folder"},
      },
      d);
  EXPECT_EQ(size_of("x.png"), png);
  EXPECT_EQ(size_of("t.csv"), csv);
  EXPECT_EQ(size_of("d.txt"), txt);
}

TEST(HostileInput, SameFileIsTheSameInodeOrTheSamePath) {
  TempDir d;
  std::ofstream(d.file("a")) << "a";
  fs::create_symlink(d.file("a"), d.file("link"));
  EXPECT_TRUE(arp::same_file(d.file("a"), d.file("link")));
  EXPECT_TRUE(arp::same_file(d.file("a"), d.path() + "/./a"));
  EXPECT_TRUE(arp::same_file(d.file("new"), d.path() + "/../" + fs::path(d.path()).filename().string() + "/new"));
  EXPECT_FALSE(arp::same_file(d.file("a"), d.file("b")));
  EXPECT_THROW(arp::check_output_paths({{"--out", d.file("link")}}, {{"--in", d.file("a")}}), arp::InputError);
  EXPECT_NO_THROW(arp::check_output_paths({{"--out", d.file("b")}}, {{"--in", d.file("a")}}));
  EXPECT_EQ(d.entries(), 2u);  // the writability probe left nothing behind
}
