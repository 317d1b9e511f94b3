// A run stopped early (Ctrl-C, SIGTERM, or any stop request) loses nothing it
// finished: the report and CSV hold every frame scanned out and say the run
// is incomplete, images written are whole, no temporary file is left, and
// the exit status says which signal stopped it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "TestSupport.hpp"
#include "sim/Session.hpp"

using namespace arp;
using arp::test::TempDir;
namespace fs = std::filesystem;

namespace {

using arp::test::load_json;

size_t lines_of(const std::string& path) {
  std::ifstream in(path);
  size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}

// Hidden temporaries (".NAME.tmp-PID...") anywhere under the folder.
size_t temporaries_in(const std::string& dir) {
  size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) ++n;
  return n;
}

}  // namespace

TEST(RunInterruption, AStopRequestEndsTheRunWithEveryFinishedFrameWritten) {
  TempDir d;
  sim::RunSpec spec;
  spec.frames = 40;
  spec.out.out_dir = d.file("img");
  spec.out.every = 2;
  spec.out.report = d.file("r.json");
  spec.out.csv = d.file("r.csv");
  spec.motion.motion = "rotate";
  sim::Session session(spec);
  int frames_seen = 0;
  session.on_frame = [&](const HmdFrame&, const stage::FrameReport&) { ++frames_seen; };
  session.stop_when = [&] { return frames_seen >= 5 ? SIGINT : 0; };
  const sim::RunSummary s = session.run();
  EXPECT_FALSE(s.complete());
  EXPECT_EQ(s.frames_done, 5);
  EXPECT_EQ(s.stop_signal, SIGINT);
  const auto r = load_json(d.file("r.json"));
  EXPECT_EQ(r["complete"], false);
  EXPECT_EQ(r["frames_done"], 5);
  ASSERT_EQ(r["frames"].size(), 5u);
  EXPECT_EQ(r["frames"][4]["frame"], 4);
  EXPECT_EQ(lines_of(d.file("r.csv")), 1u + 5u);  // header and five rows
  EXPECT_TRUE(fs::exists(d.file("img/frame_000004.png")));
  EXPECT_FALSE(fs::exists(d.file("img/frame_000006.png")));
  EXPECT_EQ(temporaries_in(d.path()), 0u);
  EXPECT_NE(s.lines()[1].find("STOPPED by SIGINT after 5 of 40 frames"), std::string::npos) << s.lines()[1];
}

TEST(RunInterruption, ARunThatIsNotStoppedSaysItIsComplete) {
  TempDir d;
  sim::RunSpec spec;
  spec.frames = 3;
  spec.out.every = 0;
  spec.out.report = d.file("r.json");
  sim::Session session(spec);
  session.stop_when = [] { return 0; };
  const sim::RunSummary s = session.run();
  EXPECT_TRUE(s.complete());
  EXPECT_EQ(load_json(d.file("r.json"))["complete"], true);
  EXPECT_EQ(load_json(d.file("r.json"))["frames"].size(), 3u);
}

// The real thing: arpsim run at a cycle-accurate level with a waveform,
// interrupted by SIGINT (then SIGTERM at the functional level) once it has
// written its first image.
TEST(RunInterruption, SigintAndSigtermStopTheCommandCleanly) {
  for (const auto& [level, sig] : {std::pair<std::string, int>{"cycle", SIGINT}, {"functional", SIGTERM}}) {
    TempDir d;
    std::vector<std::string> args = {arp::test::kArpsim, "run", "-q", "--fidelity", level, "--frames", "100000", "--every", "1",
                                     "--out-dir", d.file("img"), "--report", d.file("r.json"), "--csv", d.file("r.csv"),
                                     "--set", "display.eyes=1"};
    if (level != "functional") args.insert(args.end(), {"--vcd", d.file("w"), "--vcd-lines", "0:100000"});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int out = ::open(d.file("stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::dup2(out, STDOUT_FILENO);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(out);
    // Wait for the first finished frame, then ask it to stop.
    const auto t0 = std::chrono::steady_clock::now();
    while (!fs::exists(d.file("img/frame_000000.png")) && std::chrono::steady_clock::now() - t0 < std::chrono::minutes(5))
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << level;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << level;
    const auto r = load_json(d.file("r.json"));
    EXPECT_EQ(r["complete"], false) << level;
    const int64_t done = r["frames_done"].get<int64_t>();
    EXPECT_GE(done, 1) << level;
    EXPECT_LT(done, 100000) << level;
    EXPECT_EQ(r["frames"].size(), static_cast<size_t>(done)) << level;
    EXPECT_EQ(lines_of(d.file("r.csv")), static_cast<size_t>(done) + 1) << level;
    if (level != "functional") {
      EXPECT_GT(fs::file_size(d.file("w.vcd")), 1000u) << level;  // the waveform up to the stop
    }
    EXPECT_EQ(temporaries_in(d.path()), 0u) << level;
  }
}

#include "lab/LatencyStudy.hpp"

// The latency laboratory stops as the step in flight finishes after a stop request: the
// steps before it wrote whole files, the table and summary (written last) are
// not written, and nothing temporary is left.
TEST(LatencyInterruption, AStopRequestEndsTheStudyBeforeTheNextStep) {
  TempDir d;
  lab::LatencySpec spec;
  spec.out_dir = d.file("lab");
  spec.frames = 30;
  spec.no_apparatus = true;
  lab::LatencyStudy study(spec);
  const int64_t steps = study.steps();
  ASSERT_GT(steps, 10);
  int polls = 0;
  std::vector<std::string> done;
  study.on_step = [&done](const std::string& what) { done.push_back(what); };
  study.stop_requested = [&polls, steps] { return ++polls > steps - 3; };  // stop in the sweeps, after the architectures
  try {
    study.run();
    FAIL() << "the study ran to its end";
  } catch (const lab::StudyStopped& e) {
    EXPECT_EQ(done.size(), static_cast<size_t>(steps - 3));
    EXPECT_FALSE(std::string(e.what()).empty());
  }
  EXPECT_TRUE(fs::exists(d.file("lab/error-over-time.csv")));  // written after the architectures
  EXPECT_FALSE(fs::exists(d.file("lab/table.md")));
  EXPECT_FALSE(fs::exists(d.file("lab/summary.json")));
  EXPECT_EQ(temporaries_in(d.path()), 0u);
}

// `arpsim latency` asked to stop by SIGINT once its first step is done: exit
// 130, a message naming what was not run, no table, no temporaries.
TEST(LatencyInterruption, SigintStopsTheCommandCleanly) {
  TempDir d;
  std::vector<std::string> args = {arp::test::kArpsim, "latency", "--frames", "600", "--no-apparatus", "--out-dir", d.file("lab")};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int err[2];
  ASSERT_EQ(::pipe(err), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::dup2(err[1], STDERR_FILENO);
    ::close(err[0]);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(err[1]);
  // The progress line's first update comes after the first step; dozens more steps (the sweeps) follow.
  std::string said;
  char buf[512];
  while (said.find('%') == std::string::npos) {
    const ssize_t n = ::read(err[0], buf, sizeof buf);
    if (n <= 0) break;
    said.append(buf, static_cast<size_t>(n));
  }
  ::kill(pid, SIGINT);
  for (ssize_t n; (n = ::read(err[0], buf, sizeof buf)) > 0;) said.append(buf, static_cast<size_t>(n));
  ::close(err[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << said;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << said;
  EXPECT_NE(said.find("arpsim latency: stopped by SIGINT after '"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(d.file("lab/table.md")));
  EXPECT_EQ(temporaries_in(d.path()), 0u);
}
