// The simulated latency apparatus: the oscilloscope's edges (pendulum
// photodiode, render start, screen photodiode) against the models' internal
// timestamps. Olano et al. read latency off the edges; the two must agree
// within the oscilloscope's resolution -- each edge is seen at the first
// sample after it, so the difference is at most two sample intervals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lab/ArchitectureSet.hpp"
#include "lab/apparatus/Oscilloscope.hpp"

using namespace arp;
using namespace arp::lab;

TEST(ApparatusBench, EdgesOnTheOscilloscopeAgreeWithInternalTimestamps) {
  dp::ArpConfig c;
  c.timing = ntsc_like_timing();
  c.lens.fov_deg = 60;
  const DisplayRaster d(c.timing, c.lens.fov_deg);
  apparatus::PendulumSpec ps;  // 20 deg, 1.2 s: a low point every 0.6 s
  const TrackerModel tm{1000, 0.033};
  const int64_t first = 30, frames = 100;  // 0.5 s .. 3.8 s
  const double t_end = static_cast<double>(d.photon_ps(first + frames, 0, 0)) * 1e-12;
  const TrackerFeed feed(apparatus::pendulum_motion(ps, t_end + 0.2, 5000), tm, "pendulum");
  auto archs = make_architectures(d, c, LabConfig{}, "bench");
  std::vector<apparatus::ChannelEvents> ch;
  for (auto& a : archs) ch.push_back(apparatus::observe(*a, d, feed, Prediction::None, first, frames));
  const auto dir = std::filesystem::temp_directory_path() / "arpsim_apparatus_bench";
  std::filesystem::create_directories(dir);
  apparatus::ScopeRun run;
  run.start_ps = d.photon_ps(first, 0, 0);
  run.end_ps = d.photon_ps(first + frames, 0, 0);
  run.vcd_path = (dir / "scope").string();
  const apparatus::ScopeEdges e = apparatus::run_oscilloscope(ps, ch, run);
  // The pendulum passes its low point five times in the window.
  EXPECT_EQ(e.pendulum_rise.size(), 5u);
  EXPECT_EQ(e.pendulum_fall.size(), 5u);
  const double two_samples_ms = 2 * ps.scope_sample_s * 1e3;
  for (size_t i = 0; i < ch.size(); ++i) {
    SCOPED_TRACE(ch[i].name);
    const auto m = apparatus::analyse(ps, e, i, ch[i]);
    ASSERT_GE(m.passages.size(), 4u);
    EXPECT_LE(m.max_disagreement_ms, two_samples_ms + 1e-9);
    for (const auto& p : m.passages) {
      // The pendulum pulse's middle is the low point (the swing is symmetric).
      EXPECT_NEAR(p.pendulum_mid_s, p.crossing_s, ps.scope_sample_s);
      // Render start to screen: the model's compute-to-photon time.
      EXPECT_NEAR(p.rendering_ms, p.internal_render_ms, two_samples_ms);
      // No prediction: the report the edge's image used was sampled after the low point, and at most a
      // tracker period after the last computation for the centre pixel that still saw the other side
      // (the centre pixel is drawn once a frame: 33.4 ms on this interlaced display).
      const double frame_ms = static_cast<double>(d.timing().cycles_to_ps(d.timing().frame_cycles())) * 1e-9;
      EXPECT_LE(p.internal_report_ms, p.external_total_ms + two_samples_ms);
      EXPECT_GE(p.internal_report_ms, p.external_total_ms - frame_ms - 1.0 - two_samples_ms);
      // Tracking latency covers at least the tracker's 33 ms.
      EXPECT_GE(p.tracking_ms, 33.0 - two_samples_ms);
    }
    if (ch[i].name == "slats") {
      // One field from the transform start to the start of the field, plus the scan to the centre pixel.
      EXPECT_NEAR(m.mean_rendering_ms, 1e3 / 59.94 + (120 * 780 + 300) / 12'272'727.0 * 1e3, 0.01);
    }
  }
  // The waveform has the three kinds of signal.
  std::ifstream in(dir / "scope.vcd");
  std::stringstream ss;
  ss << in.rdbuf();
  for (const char* sig : {"pendulum_photodiode", "pendulum_angle_mdeg", "slats_render_start", "arp_pixel_screen_photodiode"})
    EXPECT_NE(ss.str().find(sig), std::string::npos) << sig;
  std::filesystem::remove_all(dir);
}
