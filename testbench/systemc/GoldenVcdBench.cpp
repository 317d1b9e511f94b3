// Golden-waveform bench: one frame of a tiny configuration through the
// detailed model, traced completely, must equal the reviewed waveform in
// testbench/systemc/golden/tiny_rtl.vcd once the header's date and version
// are stripped. Any change in what a stage does on which clock shows up
// here. To accept a deliberate change: ARPSIM_UPDATE_GOLDEN=1, then review
// the diff of the golden file.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "BenchSupport.hpp"

using namespace arp;

namespace {

dp::ArpConfig tiny() {
  dp::ArpConfig c;
  c.timing = dp::VideoTimingConfig::mode(1, {8, 2, 2, 2}, {4, 1, 1, 1}, c.timing.pixel_clock_hz);
  c.memory.count = 1;
  c.memory.face_size = 4;
  c.pipeline.aa = dp::AaMode::Off;
  c.timed.host_clock_hz = 50'000'000;
  return c;
}

// The file without its $date and $version sections.
std::string stripped(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  std::string line;
  bool skip = false;
  while (std::getline(in, line)) {
    if (line.rfind("$date", 0) == 0 || line.rfind("$version", 0) == 0) skip = true;
    if (!skip) out << line << "\n";
    if (skip && line.find("$end") != std::string::npos) skip = false;
  }
  return out.str();
}

}  // namespace

TEST(GoldenVcd, TinyFrameThroughTheDetailedModelMatchesTheReviewedWaveform) {
  const dp::ArpConfig c = tiny();
  dp::DisplayMemorySet mem(c.memory, 1);
  bench::fill_memories(mem);
  const auto o = dp::OrientationStream::constant(dp::from_yaw_pitch_roll_deg(30, 10, 0));
  // A host job during the frame, so the write port and the swap show in the waveform too.
  const dp::VideoTiming t(c.timing);
  stage::HostWriteJob job;
  job.start_ps = t.cycles_to_ps(t.frame_start_cycle(1) + 5);
  job.eye = 0;
  job.memory = 0;
  for (uint16_t i = 0; i < 4; ++i) job.texels.push_back({5, i, i, 0xff0000u, 3});
  stage::TimedInputs in = bench::inputs(c, mem, o, 1, 1);
  in.host_jobs = {job};
  const std::string dir = std::filesystem::temp_directory_path() / ("arpsim-golden-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  scm::TimedRunOptions opt;
  opt.fidelity = scm::Fidelity::Detailed;
  opt.vcd.path = dir + "/tiny";
  const scm::TimedResult r = scm::run_timed(in, opt);
  EXPECT_EQ(r.swaps, 1);
  const std::string got = stripped(dir + "/tiny.vcd");
  const std::string golden = std::string(ARPSIM_SOURCE_DIR) + "/testbench/systemc/golden/tiny_rtl.vcd";
  if (std::getenv("ARPSIM_UPDATE_GOLDEN")) std::ofstream(golden) << got;
  const std::string want = stripped(golden);
  EXPECT_GT(got.size(), 1000u);
  EXPECT_EQ(got, want) << "the waveform changed; compare " << dir << "/tiny.vcd with " << golden;
  if (got == want) std::filesystem::remove_all(dir);
}
