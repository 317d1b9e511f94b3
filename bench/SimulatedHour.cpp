// An hour of simulated time through the functional model, every frame
// rendered (no fast-forward: the latch runs on every frame), with the head
// tracker in the loop: the drift scenario's truth (tracker/DriftScenario:
// bursts of 150 deg/s shaking, 3 s still) read by a biased, noisy IMU at
// 1 kHz, fused (tracker/Fusion, defaults) and streamed into the orientation
// register as it goes. What it measures, at 1, 10, 30 and 60 minutes:
// - every pixel's photon time against the closed form floor(N 10^12 / f_pixel)
//   ps for its clock cycle N (exact integers): the drift must stay zero;
// - the age of the sample each frame's first line latched (photon time -
//   sample time): bounded by a tracker period, a line and the lead, however
//   long the run;
// - the fused quaternion's norm before the renderer normalises it, and the
//   fused orientation against the truth (what the user sees drift);
// - resident memory now and at its peak: flat, the stream trimmed behind the
//   run.
// The display is small (stereo 64 x 48 at exactly 60 Hz, one memory of 64^2
// faces) so the hour takes minutes; the pixel path's cost per frame is what
// bench/timed-speed.sh and `arpsim tradeoff` measure.
// Usage: arp_simulated_hour [MINUTES (default 60)] [CSV]   (CSV: one row per simulated minute)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "common/AtomicFile.hpp"
#include "common/ProgressLine.hpp"
#include "common/ResourceUsage.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "tracker/DriftScenario.hpp"
#include "tracker/Fusion.hpp"
#include "tracker/SyntheticImu.hpp"

namespace {

__extension__ typedef __int128 i128;  // cycles x 10^12 overflows 64 bits within the hour at MHz clocks

constexpr int64_t kSamplePs = 1'000'000'000;  // 1 kHz tracker

struct Minute {
  int64_t minute = 0, frames = 0;
  double drift_deg = 0, tilt_deg = 0, norm_error = 0, latch_age_max_us = 0, rss_mb = 0, peak_mb = 0, wall_s = 0;
  int64_t photon_error_ps = 0;  // largest |photon - closed form| so far
  size_t samples_held = 0;
};

double tilt_deg(const glm::dquat& est, const glm::dquat& tru) {
  const glm::dvec3 a = glm::conjugate(est) * glm::dvec3(0, 1, 0), b = glm::conjugate(tru) * glm::dvec3(0, 1, 0);
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
}

}  // namespace

int main(int argc, char** argv) {
  using namespace arp;
  const double minutes = argc > 1 ? std::atof(argv[1]) : 60.0;
  const std::string csv = argc > 2 ? argv[2] : "";
  if (argc > 3 || !(minutes >= 1.0 && minutes <= 600.0)) {
    std::fprintf(stderr, "usage: %s [MINUTES 1..600 (default 60)] [CSV]\n", argv[0]);
    return 2;
  }
  dp::ArpConfig c;
  c.timing.h_active = 64;
  c.timing.v_active = 48;
  c.timing.pixel_clock_hz = 1'249'920;  // 224 x 93 clocks a frame: exactly 60 Hz
  c.memory.count = 1;
  c.memory.face_size = 64;
  const FunctionalModel model(c);
  const dp::VideoTiming& vt = model.timing();
  const int64_t hz = c.timing.pixel_clock_hz, frame_cycles = vt.frame_cycles();
  if (frame_cycles * 60 != hz) {
    std::fprintf(stderr, "%s: the display is not exactly 60 Hz (%lld clocks a frame)\n", argv[0], static_cast<long long>(frame_cycles));
    return 1;
  }
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes);
  host::load_into_memories(mem, 0, host::make_calibration_pattern(c.memory.face_size), host::far_depth(mem.format()));

  // The tracker: truth -> IMU -> fusion, one sample per millisecond, streamed.
  const tracker::ImuNoise noise = tracker::drift_imu_noise();
  std::mt19937_64 rng(noise.seed);
  tracker::PoseSample truth = tracker::drift_truth_at(0.0);
  tracker::ImuReading prev = tracker::imu_reading(truth, noise, rng);
  tracker::Fusion fusion(tracker::FusionParams{}, truth.orientation);
  double norm_error = 0;
  auto as_sample = [](int64_t t, const glm::dquat& q) { return dp::OrientationSample{t, dp::Quat{q.w, q.x, q.y, q.z}}; };
  dp::OrientationStream stream({as_sample(0, fusion.orientation())}, "fusion");
  int64_t next_sample = 1;

  const auto frames = static_cast<int64_t>(std::llround(minutes * 3600.0));
  HmdFrame f;
  RenderOptions ro;
  ro.threads = 0;
  ro.photon_times = true;
  std::vector<int64_t> cycle_in_frame;  // each pixel's clock cycle within its frame, read off frame 0
  std::vector<Minute> rows;
  Minute now;
  const auto wall0 = std::chrono::steady_clock::now();
  ProgressLine progress("simulated hour", true, frames);
  for (int64_t k = 0; k < frames; ++k) {
    // Fuse through the end of this frame (the latch never reads past it).
    const int64_t frame_end_ps = vt.cycles_to_ps(vt.frame_start_cycle(k + 1));
    std::vector<dp::OrientationSample> more;
    while (next_sample * kSamplePs <= frame_end_ps) {
      truth = tracker::drift_truth_at(static_cast<double>(next_sample) * 1e-3);
      const tracker::ImuReading r = tracker::imu_reading(truth, noise, rng);
      fusion.update(r.gyro, r.accel, static_cast<double>(r.time_ps - prev.time_ps) * 1e-12);
      prev = r;
      const glm::dquat& q = fusion.orientation();
      norm_error = std::max(norm_error, std::abs(std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z) - 1.0));
      more.push_back(as_sample(next_sample * kSamplePs, q));
      ++next_sample;
    }
    if (!more.empty()) stream.append(more, "fusion");
    model.render(mem, stream, k, f, ro);

    if (k == 0) {
      for (int64_t t : f.photon_ps) cycle_in_frame.push_back(static_cast<int64_t>((static_cast<i128>(t) * hz + 999'999'999'999) / 1'000'000'000'000));
    }
    for (size_t i = 0; i < f.photon_ps.size(); ++i) {
      const i128 n = static_cast<i128>(k) * frame_cycles + cycle_in_frame[i];
      const auto expected = static_cast<int64_t>(n * 1'000'000'000'000 / hz);
      now.photon_error_ps = std::max(now.photon_error_ps, std::abs(f.photon_ps[i] - expected));
    }
    const size_t latched = model.latch_rule().sample(stream, k, 0, 0, 0);
    const int64_t age = f.photon_ps[f.index(0, 0, 0)] - stream[latched].time_ps;
    now.latch_age_max_us = std::max(now.latch_age_max_us, static_cast<double>(age) * 1e-6);

    // Trim behind the run: the next frame latches nothing older than a second before its start.
    const int64_t keep_from = vt.cycles_to_ps(vt.frame_start_cycle(k + 1)) - 1'000'000'000'000;
    if (keep_from > 0) stream.discard_before(keep_from);
    progress.step("frame " + std::to_string(k + 1));

    if ((k + 1) % 3600 == 0 || k + 1 == frames) {
      now.minute = (k + 1 + 3599) / 3600;
      now.frames = k + 1;
      const glm::dquat& est = fusion.orientation();
      now.drift_deg = tracker::angle_between_deg(est, truth.orientation);  // both at the last sample
      now.tilt_deg = tilt_deg(est, truth.orientation);
      now.norm_error = norm_error;
      now.rss_mb = static_cast<double>(current_resident_bytes()) / (1 << 20);
      // getrusage's peak is updated lazily by the kernel: never below the resident set just read.
      now.peak_mb = std::max(now.rss_mb, static_cast<double>(peak_resident_bytes()) / (1 << 20));
      now.samples_held = stream.held();
      now.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      rows.push_back(now);
    }
  }

  std::printf("An hour of simulated time: %lld frames at 60 Hz, functional level, stereo %dx%d, fused tracker at 1 kHz\n"
              "(drift scenario: gyro bias 0.5/-0.3/0.4 deg/s, noise 0.01 rad/s, seed 7)\n\n",
              static_cast<long long>(frames), c.timing.h_active, c.timing.v_active);
  std::printf("| after (min) | frames | photon time vs closed form, max (ps) | latched sample age, max (us) | fusion |q|-1, max | "
              "fused vs truth (deg) | tilt (deg) | samples held | resident (MiB) | peak resident (MiB) | wall (s) |\n"
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  std::ostringstream table;
  table << "minute,frames,photon_error_ps,latch_age_max_us,norm_error,drift_deg,tilt_deg,samples_held,rss_mib,peak_rss_mib,wall_s\n";
  for (const Minute& m : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "%lld,%lld,%lld,%.3f,%.3g,%.4f,%.4f,%zu,%.1f,%.1f,%.1f\n", static_cast<long long>(m.minute),
                  static_cast<long long>(m.frames), static_cast<long long>(m.photon_error_ps), m.latch_age_max_us, m.norm_error,
                  m.drift_deg, m.tilt_deg, m.samples_held, m.rss_mb, m.peak_mb, m.wall_s);
    table << line;
    if (m.minute == 1 || m.minute == 10 || m.minute == 30 || m.minute == 60 || &m == &rows.back())
      std::printf("| %lld | %lld | %lld | %.1f | %.2g | %.3f | %.3f | %zu | %.1f | %.1f | %.0f |\n", static_cast<long long>(m.minute),
                  static_cast<long long>(m.frames), static_cast<long long>(m.photon_error_ps), m.latch_age_max_us, m.norm_error,
                  m.drift_deg, m.tilt_deg, m.samples_held, m.rss_mb, m.peak_mb, m.wall_s);
  }
  const Minute& first = rows.front();
  const Minute& last = rows.back();
  std::printf("\nresident memory, last / first minute: %.3f; photon-time drift %s\n", last.rss_mb / first.rss_mb,
              last.photon_error_ps == 0 ? "zero" : "NOT ZERO");
  if (!csv.empty()) {
    try {
      write_text_atomic(csv, table.str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
      return 2;
    }
  }
  return last.photon_error_ps == 0 ? 0 : 1;
}
