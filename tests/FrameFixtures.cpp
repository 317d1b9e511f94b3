#include "FrameFixtures.hpp"

#include <algorithm>
#include <vector>

#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"

namespace arp::test {

void fill_layered(dp::DisplayMemorySet& mem) {
  const auto& fmt = mem.format();
  const int S = fmt.face_size;
  host::load_into_memories(mem, 0, host::make_calibration_pattern(S), host::far_depth(fmt));
  const uint32_t near = fmt.empty_depth() / 3;
  for (int e = 0; e < mem.eyes(); ++e)
    for (int m = 1; m < std::min(3, mem.count()); ++m) {
      auto& b = mem.bank(e, m);
      for (int f = 0; f < 6; ++f)
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x) {
            const bool in = m == 1 ? ((x * 7 / S + y * 5 / S) % 2 == 0) : ((x * 3 / S) == 1 && f != 4);
            if (in) b.write(f, x, y, fmt.pack_rgb8(m == 1 ? 250 : 30, 40 * m, 255 - 60 * f), near);
          }
      b.commit();
      b.vblank();
    }
}

dp::OrientationStream turning(const dp::VideoTiming& t, int64_t frame, double deg_per_ms) {
  std::vector<dp::OrientationSample> s;
  const int64_t t0 = t.cycles_to_ps(t.frame_start_cycle(frame)) - 2'000'000'000;
  for (int i = 0; i < 24; ++i)
    s.push_back({t0 + int64_t{i} * 1'000'000'000,
                 dp::from_yaw_pitch_roll_deg(30.0 + deg_per_ms * i, 20.0 - 0.3 * deg_per_ms * i, 5.0 + 0.2 * i)});
  return dp::OrientationStream(s, "test");
}

dp::ArpConfig small_display(dp::ArpConfig c) {
  const auto t = c.timing;
  c.timing = dp::VideoTimingConfig::mode(t.eyes, {160, 8, 16, 16}, {120, 2, 2, 6}, 1'400'000);
  c.timing.eye_scan = t.eye_scan;
  c.timing.fields_per_frame = t.fields_per_frame;
  return c;
}

}  // namespace arp::test
