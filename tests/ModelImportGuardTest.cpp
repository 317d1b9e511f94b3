// Model import that cannot take the process down (host/scene/ModelImport):
// header counts checked against the file before import, and the importer in
// a watched helper process -- a hang, a crash, runaway memory, garbage or a
// flood of messages from it is a clear InputError naming the file, within
// limits of a few seconds here. The misbehaving importer is a stand-in
// (tests/import/FakeImporter.cpp) so the guard is tested whatever assimp does;
// real broken files go through the real importer too.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "host/scene/ModelImport.hpp"

using namespace arp;
using arp::test::error_of;
using arp::test::TempDir;

namespace {

// The stand-in importer for one test, in one mode.
class FakeImporter {
 public:
  explicit FakeImporter(const char* mode) {
    setenv("ARPSIM_IMPORT_HELPER", ARPSIM_FAKE_IMPORTER, 1);
    setenv("ARP_FAKE_IMPORTER", mode, 1);
  }
  ~FakeImporter() {
    unsetenv("ARPSIM_IMPORT_HELPER");
    unsetenv("ARP_FAKE_IMPORTER");
  }
};

std::string write(const TempDir& d, const std::string& name, const std::string& text) {
  std::ofstream(d.file(name), std::ios::binary) << text;
  return d.file(name);
}

const std::string kCube = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

}  // namespace

TEST(ModelImportGuard, HeaderCountsBeyondTheFileAreRefusedBeforeImport) {
  TempDir d;
  struct Case {
    std::string name, text, says;
  };
  std::string stl(80, ' ');
  stl += std::string("\xff\xff\xff\x0f", 4);  // 268 million triangles, none there
  for (const Case& c : std::vector<Case>{
           {"truncated.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float32 x\nproperty float", "truncated"},
           {"huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\nend_header\n", "1000000000"},
           {"huge.off", "OFF\n1000000000 1 0\n0 0 0\n", "1000000000"},
           {"huge.stl", stl, "268435455"},
           {"bad.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":100000000,"uri":"data:application/octet-stream;base64,AAAA"}]})",
            "byteLength"},
           {"badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n", "quad"},
           // Found by the fuzzer: "end_header" inside another line; assimp's reader hangs on it.
           {"inside.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nelend_headerted\n0\n1\n2\n", "no end_header line"},
           // An OFF face's index beyond the vertices: assimp took it as the last vertex, without a word.
           {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "line 6: face 0: vertex index \"5\" is not one of the 3 vertices"},
           {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "vertex index \"-1\""},
           {"short.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n# a comment\n3 0 1\n", "line 6: face 0: declares 3 vertices and lists 2"}}) {
    const auto e = error_of([&] { host::import_model(write(d, c.name, c.text)); });
    EXPECT_EQ(e.source(), d.file(c.name));
    EXPECT_NE(e.what() + std::string(), "no error") << c.name;
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << c.name << ": " << e.what();
  }
  // Valid OFFs: the counts on the magic's line, comments, blank lines and a face's colour after its indices; the
  // counts split over lines, which assimp reads and the face check leaves to it (it had refused them).
  for (const std::string valid : {"OFF 3 1 0\n# c\n0 0 0\n\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n", "OFF\n3\n1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                                   "OFF\n3 1\n0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"})
    EXPECT_EQ(host::import_model(write(d, "valid.off", valid)).indices.size(), 3u) << valid;
  EXPECT_NE(std::string(error_of([] { host::import_model("/usr/share/assimp/models/invalid/OutOfMemory.off"); }).what()).find("declares"),
            std::string::npos);
  EXPECT_NE(std::string(error_of([] { host::import_model("/dev/zero"); }).what()).find("regular file"), std::string::npos);
}

TEST(ModelImportGuard, AHungImporterIsStoppedAtItsDeadline) {
  TempDir d;
  FakeImporter fake("hang");
  const auto t0 = std::chrono::steady_clock::now();
  const auto e = error_of([&] { host::import_model(write(d, "m.ply", kCube), {2.0, 1ull << 30}); });
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NE(std::string(e.what()).find("took longer than 2 s"), std::string::npos) << e.what();
  EXPECT_GE(took, 2.0);  // stopped at the deadline, not before (an upper bound would test the machine's speed)
}

// The limits from the environment are read strictly and named: "inf" or 1e300 seconds overflowed the deadline
// and blamed a valid model ("took longer than -2147483648 s"), "-1" MiB wrapped to a limit of none.
TEST(ModelImportGuard, LimitsFromTheEnvironmentAreCheckedAndNamed) {
  const auto with = [](const char* name, const char* value) {
    setenv(name, value, 1);
    std::string what;
    try {
      const host::ImportLimits l = host::ImportLimits::from_environment();
      what = "seconds " + std::to_string(l.seconds) + " bytes " + std::to_string(l.max_bytes);
    } catch (const arp::InputError& e) {
      what = e.what();
    }
    unsetenv(name);
    return what;
  };
  for (const char* bad : {"inf", "1e300", "nan", "0", "-5", "60s", "0.0001"})
    EXPECT_NE(with("ARPSIM_IMPORT_SECONDS", bad).find("ARPSIM_IMPORT_SECONDS: " + std::string(bad) + ": must be a number of seconds"),
              std::string::npos) << bad;
  for (const char* bad : {"-1", "0", "1.5", "18446744073709551615", "16777217"})
    EXPECT_NE(with("ARPSIM_IMPORT_MAX_MB", bad).find("ARPSIM_IMPORT_MAX_MB: " + std::string(bad) + ": must be a whole number"),
              std::string::npos) << bad;
  EXPECT_EQ(with("ARPSIM_IMPORT_SECONDS", "2.5"), "seconds 2.500000 bytes " + std::to_string(3ull << 30));
  EXPECT_EQ(with("ARPSIM_IMPORT_MAX_MB", "16777216"), "seconds 60.000000 bytes " + std::to_string(1ull << 44));
}

TEST(ModelImportGuard, AnImporterThatGrowsPastTheMemoryLimitIsStopped) {
  TempDir d;
  FakeImporter fake("hog");
  const auto e = error_of([&] { host::import_model(write(d, "m.ply", kCube), {60.0, 256ull << 20}); });
  EXPECT_NE(std::string(e.what()).find("more than 256 MB"), std::string::npos) << e.what();
}

TEST(ModelImportGuard, AnImporterThatWritesWithoutEndIsStopped) {
  TempDir d;
  FakeImporter fake("stream");
  const auto e = error_of([&] { host::import_model(write(d, "m.ply", kCube), {60.0, 64ull << 20}); });
  EXPECT_NE(std::string(e.what()).find("wrote more than 64 MB"), std::string::npos) << e.what();
}

TEST(ModelImportGuard, CrashesGarbageAndFloodsBecomeOneClearError) {
  TempDir d;
  const std::string f = write(d, "m.ply", kCube);
  {
    FakeImporter fake("abort");
    EXPECT_NE(std::string(error_of([&] { host::import_model(f); }).what()).find("crashed"), std::string::npos);
  }
  {
    FakeImporter fake("garbage");
    EXPECT_NE(std::string(error_of([&] { host::import_model(f); }).what()).find("no mesh"), std::string::npos);
  }
  {
    FakeImporter fake("refuse");
    const auto e = error_of([&] { host::import_model(f); });
    EXPECT_EQ(e.reason(), "the importer refused it");
  }
  {
    FakeImporter fake("flood");
    const auto e = error_of([&] { host::import_model(f); });
    EXPECT_LT(e.reason().size(), 100u);  // quoted, not a flood
  }
}

TEST(ModelImportGuard, RealModelsAndRealBrokenFilesGoThroughTheHelper) {
  const host::Mesh bunny = host::import_model("/usr/share/glmark2/models/bunny.obj");
  EXPECT_GT(bunny.triangles(), 1000u);
  EXPECT_EQ(bunny.normals.size(), bunny.positions.size());
  TempDir d;
  // A model cut off mid-data (assimp alone aborts the process on this one).
  std::ifstream in("/usr/share/assimp/models/PLY/Wuson.ply", std::ios::binary);
  std::string wuson((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(wuson.size(), 300000u);
  const auto cut = error_of([&] { host::import_model(write(d, "cut.ply", wuson.substr(0, 300000))); });
  EXPECT_EQ(cut.source(), d.file("cut.ply"));
  EXPECT_NE(cut.reason(), "no error");
  for (const char* f : {"/usr/share/assimp/models/glTF2/IndexOutOfRange/IndexOutOfRange.gltf",
                        "/usr/share/assimp/models/glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"}) {
    if (!std::ifstream(f)) continue;  // not every assimp-testmodels version has them
    const auto e = error_of([&] { host::import_model(f); });
    EXPECT_EQ(e.source(), f);
    EXPECT_NE(e.reason(), "no error") << f;
  }
}
