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
#include <utility>
#include <vector>

#include "TestSupport.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"

using arp::test::run_command;
using arp::test::read_text;
using arp::test::TempDir;
namespace fs = std::filesystem;

namespace {

using arp::test::kArpsim;
const std::string kData = std::string(ARPSIM_SOURCE_DIR) + "/tests/data/hostile/";

struct Case {
  std::string args;  // after "arpsim "
  int status;        // 2: bad input (a file, a value, a malformed option)
  std::string says;  // part of the message
};

// The group's cases of tests/data/hostile/refusals.txt, $H and $D replaced by the data folder and `d`.
std::vector<Case> refusals(const std::string& group, const TempDir& d) {
  std::vector<Case> cases;
  std::ifstream in(kData + "refusals.txt");
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    for (size_t at = 0;;) {
      const size_t bar = line.find(" | ", at);
      f.push_back(line.substr(at, bar == std::string::npos ? std::string::npos : bar - at));
      if (bar == std::string::npos) break;
      at = bar + 3;
    }
    EXPECT_EQ(f.size(), 4u) << "refusals.txt line " << number << ": " << line;
    if (f.size() != 4) continue;
    // A mistyped group would never run: every line belongs to one of the tests' groups.
    EXPECT_TRUE(f[0] == "files" || f[0] == "times" || f[0] == "numbers" || f[0] == "outputs")
        << "refusals.txt line " << number << ": no test reads group '" << f[0] << "'";
    if (f[0] != group) continue;
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"$H", kData.substr(0, kData.size() - 1)}, {"$D", d.path()}})
      for (size_t at; (at = f[3].find(key)) != std::string::npos;) f[3].replace(at, key.size(), value);
    cases.push_back({f[3], std::stoi(f[1]), f[2]});
  }
  return cases;
}

void expect_refused(const std::string& group, const TempDir& d) {
  const std::vector<Case> cases = refusals(group, d);
  EXPECT_GE(cases.size(), 5u) << group;  // the table is read
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
  expect_refused("files", d);
}

TEST(HostileInput, TimesOutsideThe64BitPicosecondRangeAreRefusedWithTheLimit) {
  TempDir d;
  expect_refused("times", d);
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

// An endless trace on standard input, every sample at one time: refused once it is denser than any tracker
// (kMaxSampleRateHz), while small -- it filled the memory until the allocator failed ("internal error"). A stream
// at ten times that rate, ending, is read (the warnings say it is implausible).
TEST(HostileInput, AnEndlessTraceOfOneTimeIsRefusedBeforeItFillsTheMemory) {
  const auto r = run_command("(echo time_s,qw,qx,qy,qz; yes 0,1,0,0,0) | timeout 120 " + kArpsim + " run -q --frames 1 --every 0 --trace -");
  EXPECT_EQ(r.status, 2) << r.output.substr(0, 2000);
  EXPECT_NE(r.output.find("-: line 1000002: 1000001 samples within 0 s: more than 1000000 a second, faster than any tracker"),
            std::string::npos)
      << r.output.substr(0, 2000);
  const auto fast = run_command("(echo time_s,qw,qx,qy,qz; seq -f '%.12f,1,0,0,0' 0 0.0000001 0.1) | timeout 120 " + kArpsim +
                                " run -q --frames 1 --every 0 --trace -");
  EXPECT_EQ(fast.status, 0) << fast.output.substr(0, 2000);
  EXPECT_NE(fast.output.find("implausible for a head tracker"), std::string::npos) << fast.output.substr(0, 2000);
}

// A command's printed output that cannot be written (a full disk: /dev/full) is an error, not a success with an
// empty file behind it.
TEST(HostileInput, PrintedOutputThatCannotBeWrittenIsAnError) {
  for (const std::string args : {"config", "config --list"}) {
    const auto r = run_command("{ " + kArpsim + " " + args + " > /dev/full; }");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("standard output: the command's output was not written whole"), std::string::npos) << args << "\n" << r.output;
  }
}

// A display whose frames take more memory than the process has (here an address-space limit of 1.5 GB) is
// refused naming display.h_active before anything is allocated: it ended in std::bad_alloc ("internal error"),
// `run` leaving an empty --out-dir behind.
TEST(HostileInput, ADisplayLargerThanTheMemoryIsRefusedBeforeAnythingIsAllocated) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "an address-space limit leaves no room for the sanitizer's shadow memory";
#endif
  TempDir d;
  for (const std::string args : {"frame -o out.png", "run -q --frames 1 --out-dir o"}) {
    const auto r = run_command("cd " + d.path() + " && ulimit -v 1500000 && " + kArpsim + " " + args +
                               " --set display.h_active=8192 --set display.v_active=8192");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("display.h_active: a run of a 8192 x 8192 display may need up to"), std::string::npos) << args << "\n" << r.output;
  }
  EXPECT_EQ(d.entries(), 0u) << "no image, no --out-dir";
}

// A scene of many finely divided spheres (a million triangles each at 1024 segments) whose meshes would not fit
// the memory (here an address-space limit of 1.5 GB) is refused naming the object that tips it: it ended in
// std::bad_alloc ("internal error").
TEST(HostileInput, AScenesMeshesLargerThanTheMemoryAreRefusedNamingTheObject) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "an address-space limit leaves no room for the sanitizer's shadow memory";
#endif
  TempDir d;
  std::string objects;
  for (int i = 0; i < 40; ++i)
    objects += std::string(i ? ", " : "") + R"({"name": "s)" + std::to_string(i) + R"(", "sphere": 0.1, "segments": 1024, "position": [0, 0, -3]})";
  std::ofstream(d.file("spheres.json")) << R"({"objects": [)" + objects + "]}";
  const auto r = run_command("cd " + d.path() + " && ulimit -v 1500000 && " + kArpsim + " frame -o out.png --scene spheres.json");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("spheres.json: objects["), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("with this object the scene's meshes and the renderer's copies of them take"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d.file("out.png")));
}

// A trace that starts after the run's first frame is said (its first sample stands for the motion before it),
// once; one that covers the start is not.
TEST(HostileInput, ATraceStartingAfterTheRunIsSaid) {
  TempDir d;
  std::ofstream(d.file("late.csv")) << "time_s,qw,qx,qy,qz\n5,1,0,0,0\n6,1,0,0,0\n";
  const auto r = run_command(kArpsim + " run -q --frames 2 --every 0 --trace " + d.file("late.csv"));
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string said = "warning: the trace starts at 5.000000 s, after the run's first frame at 0.000000 s";
  EXPECT_NE(r.output.find(said), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(said), r.output.rfind(said)) << "once";
  std::ofstream(d.file("early.csv")) << "time_s,qw,qx,qy,qz\n-1,1,0,0,0\n6,1,0,0,0\n";
  const auto e = run_command(kArpsim + " run -q --frames 2 --every 0 --trace " + d.file("early.csv"));
  EXPECT_EQ(e.status, 0) << e.output;
  EXPECT_EQ(e.output.find("the trace starts at"), std::string::npos) << e.output;
  // A plan says it too, once on the terminal and in its account; with no sample within the walk, that the head
  // never turned (a plan over a trace of another session's times was made without a word).
  const std::string plan = kArpsim + " plan -q --scene " + ARPSIM_SOURCE_DIR + "/scenes/sparse-room.json --walk " +
                           ARPSIM_SOURCE_DIR + "/scenes/sparse-room-walk.json --keep-widths --fill-points 2 -o " + d.file("p.json") + " --trace ";
  std::ofstream(d.file("later.csv")) << "time_s,qw,qx,qy,qz\n1000,1,0,0,0\n1000.01,1,0,0,0\n";
  const auto p = run_command(plan + d.file("later.csv"));
  EXPECT_EQ(p.status, 0) << p.output;
  EXPECT_NE(p.output.find("arpsim plan: warning: the trace " + d.file("later.csv") + " starts at 1000.000000 s, after the motion's "
                          "start at 0 s: the head before it holds its first sample, through the whole 9.6 s planned over"),
            std::string::npos) << p.output;
  EXPECT_NE(read_text(d.file("p.md")).find("**Warning**: the trace"), std::string::npos);
  const auto f = run_command(plan + d.file("early.csv"));
  EXPECT_EQ(f.status, 0) << f.output;
  EXPECT_EQ(f.output.find("the trace " + d.file("early.csv") + " starts at"), std::string::npos) << f.output;
}

// A file a model names (an OBJ's material library) that is a FIFO or a device is refused at once, named: assimp
// opened it to see whether it existed, and a FIFO stalled the import until its guard stopped it after 60 s, then
// blamed on the model's size; a device was read as a material. A regular file of that name still imports.
TEST(HostileInput, AFileAModelNamesMustBeARegularFile) {
  TempDir d;
  std::ofstream(d.file("m.obj")) << "mtllib mat.mtl\nv 0 0 -2\nv 1 0 -2\nv 0 1 -2\nf 1 2 3\n";
  std::ofstream(d.file("s.json")) << R"({"objects": [{"model": "m.obj"}]})";
  const std::string frame = kArpsim + " frame --out " + d.file("out.png") + " --scene " + d.file("s.json");
  ASSERT_EQ(::mkfifo(d.file("mat.mtl").c_str(), 0600), 0);
  const auto r = run_command(frame);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("m.obj: names mat.mtl: not a regular file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d.file("out.png")));
  fs::remove(d.file("mat.mtl"));
  fs::create_symlink("/dev/zero", d.file("mat.mtl"));
  const auto z = run_command(frame);
  EXPECT_EQ(z.status, 2) << z.output;
  EXPECT_NE(z.output.find("m.obj: names mat.mtl: not a regular file"), std::string::npos) << z.output;
  fs::remove(d.file("mat.mtl"));
  std::ofstream(d.file("mat.mtl")) << "newmtl a\nKd 1 0 0\n";
  const auto ok = run_command(frame);
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_TRUE(fs::exists(d.file("out.png")));
}

// A folder's name is only a name: gnuplot ran in --out-dir through a shell, `cd 'DIR' && gnuplot ...`, so a
// quote in the folder's name ran the rest as commands. It is spawned without a shell now, and still plots.
TEST(HostileInput, AFolderNameIsNeverRunAsACommand) {
  TempDir d;
  const std::string dir = d.file("x';touch " + d.file("PWNED") + ";'");
  const auto r = run_command(kArpsim + " latency -q --frames 4 --no-sweeps --no-apparatus --out-dir \"" + dir + "\"");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(d.file("PWNED"))) << "a folder's name ran as a command";
  EXPECT_TRUE(fs::exists(dir + "/latency.png")) << r.output;
  EXPECT_TRUE(fs::exists(dir + "/latency.gp.log"));
}

// A VCD's header ends at $enddefinitions wherever it stands on its line (the format allows several commands a
// line), and not at one inside a comment; one without it is refused (refusals.txt).
TEST(HostileInput, AVcdHeaderMayEndMidLine) {
  TempDir d;
  std::ofstream(d.file("w.vcd")) << "$timescale 1 ps $end\n$scope module SystemC $end\n$var wire 1 ! clk $end\n"
                                    "$comment a $enddefinitions in a comment\n$end\n$var wire 1 \" probe_sig $end\n"
                                    "$upscope $end $enddefinitions $end\n#0\n1!\n#10\n0!\n";
  const auto r = run_command(kArpsim + " gtkw " + d.file("w.vcd") + " -o " + d.file("w.gtkw"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read_text(d.file("w.gtkw")).find("clk"), std::string::npos);
  EXPECT_NE(read_text(d.file("w.gtkw")).find("probe_sig"), std::string::npos) << "the header ended inside a comment";
}

// A trace that does not parse is said alone: the warning that the configuration was planned for another motion (which
// hashes the trace's text) came first, and the real error read as its consequence.
TEST(HostileInput, ATraceThatDoesNotParseIsNotPrecededByAPlansWarning) {
  TempDir d;
  const std::string run = "cd " + d.path() + " && " + kArpsim +
                          " run -q --frames 1 --scene gallery --walk gallery --set plan.motion_hash=5 --report r.json --trace ";
  const auto r = run_command(run + kData + "trace-nul.csv");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("a NUL byte"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("planned for another motion"), std::string::npos) << r.output;
  // A trace that parses still gets the warning.
  std::ofstream(d.file("t.csv")) << "time_s,qw,qx,qy,qz\n-1,1,0,0,0\n1,1,0,0,0\n";
  const auto ok = run_command(run + d.file("t.csv"));
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_NE(ok.output.find("planned for another motion"), std::string::npos) << ok.output;
}

TEST(HostileInput, NumericOptionsAreStrict) {
  TempDir d;
  expect_refused("numbers", d);
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
  ASSERT_EQ(::mkfifo(d.file("fifo").c_str(), 0600), 0);  // an output onto it would replace the node
  const auto size_of = [&](const std::string& f) { return fs::file_size(d.file(f)); };
  fs::copy_file(d.file("t.csv"), d.file("photon_000000.csv"));  // a trace with a name --out-dir would give a file
  fs::create_symlink("photon_000000.csv", d.file("link.csv"));   // and a name that leads there
  fs::create_directories(d.file("R/sub"));                         // S/.. is R, not "." as the text reads
  fs::create_directory_symlink("R/sub", d.file("S"));
  fs::copy_file(d.file("t.csv"), d.file("R/photon_000000.csv"));
  fs::copy_file(d.file("t.csv"), d.file("R/error-over-time.csv"));
  const auto png = size_of("x.png"), csv = size_of("t.csv"), txt = size_of("d.txt");
  expect_refused("outputs", d);
  EXPECT_EQ(size_of("x.png"), png);
  EXPECT_EQ(size_of("t.csv"), csv);
  EXPECT_EQ(size_of("photon_000000.csv"), csv);
  EXPECT_EQ(size_of("R/photon_000000.csv"), csv);
  EXPECT_EQ(size_of("R/error-over-time.csv"), csv);
  EXPECT_FALSE(fs::exists(d.file("frame_000000.png")));
  EXPECT_FALSE(fs::exists(d.file("o")));
  EXPECT_EQ(size_of("d.txt"), txt);
  EXPECT_TRUE(fs::is_fifo(d.file("fifo")));
}

// An output that cannot be written in full (a full disk; here a file-size limit, its signal ignored as a
// shell's `ulimit -f` leaves it) is an error naming the file and the reason, and leaves nothing: not a
// truncated image behind a success (OpenImageIO's writers do not report a short write), not the picture and
// account of a plan whose configuration failed; a format OpenImageIO can only write to a file (SGI) is read
// back. A symbolic link named as an output is replaced by the file, the file it named left as it was (never
// followed: a link planted in a shared folder must not choose what is overwritten).
TEST(HostileInput, AWriteThatFailsLeavesNothingAndSaysWhy) {
  TempDir d;
  std::ofstream(d.file("s.json")) << R"({"name": "tiny", "extent": {"min": [-5, -1, -5], "max": [5, 5, 5]},
    "objects": [{"name": "ball", "sphere": 0.3, "position": [0, 1.6, -2]}]})";
  std::ofstream(d.file("w.json")) << R"({"speed": 1.0, "points": [[0, 1.6, 0], [1, 1.6, 0]]})";
  const std::string limited = "cd " + d.path() + " && trap '' XFSZ && ulimit -f 2 && timeout 120 " + kArpsim;
  auto r = run_command(limited + " frame --scene s.json --out f.png");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("f.png: cannot write image: File too large"), std::string::npos) << r.output;
  r = run_command(limited + " frame --scene s.json --out f.sgi");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("f.sgi: cannot write image: the written file does not read back whole"), std::string::npos) << r.output;
  r = run_command(limited + " plan -q --keep-widths --objects-only --scene s.json --walk w.json -o p.json");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  // The run's CSV (a few hundred bytes) is written, its report (some kB) is not: neither appears.
  r = run_command(limited + " run -q --frames 1 --every 0 --report r.json --csv c.csv");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("r.json: cannot write the file: File too large"), std::string::npos) << r.output;
  // SystemC's VCD writer checks no write: the waveform's last line, the time it was closed, shows it whole.
  r = run_command(limited + " run -q --fidelity cycle --frames 1 --every 0 --vcd ./w.vcd --vcd-signals control");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("w.vcd: the waveform was cut short: it does not end at the time it was closed"), std::string::npos) << r.output;
  r = run_command(limited + " tracker synth --motion rotate --seconds 10 -o t.csv");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("t.csv: writing the trace failed: File too large"), std::string::npos) << r.output;
  EXPECT_EQ(d.entries(), 2u) << "only the scene and the walk: no image, no plan, no account, no CSV, no waveform, no trace, no temporary file";
  std::ofstream(d.file("real.json")) << "{}";
  fs::create_symlink("real.json", d.file("link.json"));
  r = run_command("cd " + d.path() + " && " + kArpsim + " run -q --frames 1 --every 0 --report link.json");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::is_symlink(d.file("link.json")));
  EXPECT_GT(fs::file_size(d.file("link.json")), 100u);
  EXPECT_EQ(fs::file_size(d.file("real.json")), 2u);
}

// A plot gnuplot cannot write whole (a file-size limit) is an error naming the picture, not a cut PNG behind
// "wrote ...": gnuplot writes in place and says nothing of a short write (common/Gnuplot: the picture is drawn to
// a temporary file, checked to end with its IEND chunk, then renamed into place).
TEST(HostileInput, APlotCutShortIsAnErrorAndLeavesNoPicture) {
  TempDir d;
  const auto r = run_command("cd " + d.path() + " && trap '' XFSZ && ulimit -f 16 && timeout 120 " + kArpsim +
                             " latency -q --frames 5 --no-sweeps --no-apparatus --out-dir o");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("o/error-over-time.png: writing the plot failed: gnuplot's picture was cut short"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(d.file("o/error-over-time.gp")));  // the script is whole, for the user to run again
  for (const auto& e : fs::directory_iterator(d.file("o"))) {
    EXPECT_NE(e.path().extension(), ".png") << e.path();
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  }
}

// The file-size limit's signal left at its default, as a plain `ulimit -f` leaves it: the write fails as with the
// signal ignored (arpsim ignores it), where the signal killed the run (status 153) with its temporary files left.
TEST(HostileInput, AFileSizeLimitWithItsSignalAtTheDefaultLeavesNothing) {
  TempDir d;
  const auto r = run_command("cd " + d.path() + " && trap - XFSZ && ulimit -f 2 && timeout 120 " + kArpsim +
                             " run -q --frames 2 --every 1 --photon-times --out-dir o --report r.json --csv c.csv");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  for (const auto& e : fs::recursive_directory_iterator(d.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(HostileInput, SameFileIsTheSameInodeOrTheSamePath) {
  TempDir d;
  std::ofstream(d.file("a")) << "a";
  fs::create_symlink(d.file("a"), d.file("link"));
  EXPECT_TRUE(arp::same_file(d.file("a"), d.file("link")));
  EXPECT_TRUE(arp::same_file(d.file("a"), d.path() + "/./a"));
  EXPECT_TRUE(arp::same_file(d.file("new"), d.path() + "/../" + fs::path(d.path()).filename().string() + "/new"));
  EXPECT_FALSE(arp::same_file(d.file("a"), d.file("b")));
  // Two names of one file not made yet, relative to the working folder, one with a folder part: the second
  // output would have replaced the first without a word.
  const std::string here = fs::current_path().filename().string(), none = "arpsim-no-such-output.vcd";
  ASSERT_FALSE(fs::exists(none));
  EXPECT_TRUE(arp::same_file(none, "./" + none));
  EXPECT_TRUE(arp::same_file("../" + here + "/" + none, none));
  EXPECT_FALSE(arp::same_file(none, "./other-" + none));
  EXPECT_THROW(arp::check_output_paths({{"--report", none}, {"--csv", "./" + none}}, {}), arp::InputError);
  EXPECT_THROW(arp::check_output_paths({{"--out", d.file("link")}}, {{"--in", d.file("a")}}), arp::InputError);
  EXPECT_NO_THROW(arp::check_output_paths({{"--out", d.file("b")}}, {{"--in", d.file("a")}}));
  EXPECT_EQ(d.entries(), 2u);  // the writability probe left nothing behind
}
