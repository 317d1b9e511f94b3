// arpsim live under Xvfb: the window shows exactly the pipeline's frame (the
// screenshot, read back from the renderer, equals `arpsim frame` pixel for
// pixel outside the overlay) with the latency overlay drawn in; no display
// gives a clear answer; bad options are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "LiveWindow.hpp"
#include "TestSupport.hpp"
#include "host/cubemap/ImageFiles.hpp"

using arp::test::run_command;
using arp::test::TempDir;

namespace {
using arp::test::kArpsim;
using arp::test::kXvfbRun;
}  // namespace

TEST(LiveCli, TheWindowShowsThePipelinesFrameWithTheOverlay) {
  TempDir d;
  // A still head: every frame is the frame `arpsim frame` renders at the identity.
  const auto live = run_command(kXvfbRun + kArpsim + " live -q --motion rotate --rate 0 --seconds 0.5 --screenshot " + d.file("shot.png"));
  ASSERT_EQ(live.status, 0) << live.output;
  EXPECT_NE(live.output.find("30 frames"), std::string::npos) << live.output;
  const auto ref = run_command(kArpsim + " frame --frame 29 --out " + d.file("ref.png"));
  ASSERT_EQ(ref.status, 0) << ref.output;
  const arp::host::RgbImage shot = arp::host::read_rgb8(d.file("shot.png")), want = arp::host::read_rgb8(d.file("ref.png"));
  ASSERT_EQ(shot.width, 1280);
  ASSERT_EQ(shot.height, 480);
  ASSERT_EQ(want.width, shot.width);
  ASSERT_EQ(want.height, shot.height);
  // The overlay box (top-left, dark with white text) and everything else equal to the pipeline's frame.
  const auto c = arp::test::compare_outside_overlay(shot, want);
  EXPECT_GT(c.box_w, 300);
  EXPECT_GT(c.box_h, 40);
  EXPECT_LT(c.box_h, 100);
  EXPECT_GT(c.text, 1000);  // three lines of text
  EXPECT_EQ(c.differ, 0);
}

TEST(LiveCli, NoDisplayAndBadOptions) {
  const auto none = run_command("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + kArpsim + " live --seconds 1");
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.output.find("xvfb-run"), std::string::npos) << none.output;
  for (const std::string bad : {" --scale 0", " --seconds -1", " --live wifi", " --trace a.csv --motion shake", " --record-live took.csv"}) {
    const auto r = run_command(kXvfbRun + kArpsim + " live" + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.output;
  }
  EXPECT_EQ(run_command(kArpsim + " live --help").status, 0);
}

// Ctrl-C (SIGINT) closes the window after the frame in flight: the exit status says so, the screenshot of
// the last frame shown is written whole, and no temporary file is left (SDL's own handler only posted a
// quit event, and before the window there was none).
TEST(LiveCli, CtrlCClosesTheWindowAndWritesTheScreenshot) {
  TempDir d;
  // The window's process is told from xvfb-run's (which carries the same arguments) by its name; the loop is
  // running once its progress line has appeared. Its own exit status is taken inside xvfb-run, whose own
  // status is sometimes 5 after a run stopped so: its clean-up's `rm` of its temporary directory reports
  // 130 although the directory is gone (seen with the program before and after 2026-11-28; not arpsim's
  // doing: traced, it sends no signal).
  const std::string script =
      kXvfbRun + "sh -c '" + kArpsim + " live --seconds 60 --screenshot " + d.file("shot.png") + "; echo status=$? > " +
      d.file("status") + "' > " + d.file("out.txt") + " 2>&1 & job=$!; " +
      "for i in $(seq 600); do grep -q frame " + d.file("out.txt") + " && break; sleep 0.1; done; " +
      "for p in $(pgrep -f " + d.path() + "); do [ \"$(cat /proc/$p/comm)\" = arpsim ] && kill -INT $p; done; wait $job";
  {
    std::ofstream(d.file("ctrl-c.sh")) << script << "\n";
  }
  const auto r = run_command("sh " + d.file("ctrl-c.sh"));
  EXPECT_EQ(arp::test::read_text(d.file("status")), "status=130\n") << r.output << arp::test::read_text(d.file("out.txt"));
  // The screenshot whenever the signal came: before 2026-11-28 one that came after the frame's read-back
  // (during its present or the progress line) ended the loop with none.
  const arp::host::RgbImage shot = arp::host::read_rgb8(d.file("shot.png"));
  EXPECT_EQ(shot.width, 1280);
  EXPECT_EQ(d.entries(), 4u) << "shot.png, out.txt, status and the script, nothing else";
}
