// arpsim live under Xvfb: the window shows exactly the pipeline's frame (the
// screenshot, read back from the renderer, equals `arpsim frame` pixel for
// pixel outside the overlay) with the latency overlay drawn in; no display
// gives a clear answer; bad options are refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "TestSupport.hpp"
#include "host/cubemap/ImageFiles.hpp"

using arp::test::run_command;
using arp::test::TempDir;

namespace {
using arp::test::kArpsim;
// In the sanitizer build the window's child process is not leak-checked: SDL
// leaves allocations behind in libdbus and in display back-ends it loads and
// unloads itself (not ours; every other test stays leak-checked, and ASan
// still checks this one's memory accesses).
const std::string kXvfb = "env ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" xvfb-run -a -s '-screen 0 1600x1000x24' ";
}  // namespace

TEST(LiveCli, TheWindowShowsThePipelinesFrameWithTheOverlay) {
  TempDir d;
  // A still head: every frame is the frame `arpsim frame` renders at the identity.
  const auto live = run_command(kXvfb + kArpsim + " live -q --motion rotate --rate 0 --seconds 0.5 --screenshot " + d.file("shot.png"));
  ASSERT_EQ(live.status, 0) << live.output;
  EXPECT_NE(live.output.find("30 frames"), std::string::npos) << live.output;
  const auto ref = run_command(kArpsim + " frame --frame 29 --out " + d.file("ref.png"));
  ASSERT_EQ(ref.status, 0) << ref.output;
  const arp::host::RgbImage shot = arp::host::read_rgb8(d.file("shot.png")), want = arp::host::read_rgb8(d.file("ref.png"));
  ASSERT_EQ(shot.width, 1280);
  ASSERT_EQ(shot.height, 480);
  ASSERT_EQ(want.width, shot.width);
  // The overlay box (top-left, dark with white text) and everything else equal to the pipeline's frame.
  int box_w = 0, box_h = 0;
  while (box_w < shot.width && shot.px(box_w, 1)[0] == 16) ++box_w;
  while (box_h < shot.height && shot.px(1, box_h)[0] == 16) ++box_h;
  EXPECT_GT(box_w, 300);
  EXPECT_GT(box_h, 40);
  EXPECT_LT(box_h, 100);
  int text = 0, differ = 0;
  for (int y = 0; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x) {
      const uint8_t* a = shot.px(x, y);
      if (x < box_w && y < box_h) {
        text += a[0] == 255 && a[1] == 255 && a[2] == 255;
        continue;
      }
      const uint8_t* b = want.px(x, y);
      differ += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
    }
  EXPECT_GT(text, 1000);  // three lines of text
  EXPECT_EQ(differ, 0);
}

TEST(LiveCli, NoDisplayAndBadOptions) {
  const auto none = run_command("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + kArpsim + " live --seconds 1");
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.output.find("xvfb-run"), std::string::npos) << none.output;
  for (const std::string bad : {" --scale 0", " --seconds -1", " --live wifi", " --trace a.csv --motion shake"}) {
    const auto r = run_command(kXvfb + kArpsim + " live" + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.output;
  }
  EXPECT_EQ(run_command(kArpsim + " live --help").status, 0);
}
