#include "BenchSupport.hpp"

#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"

namespace arp::bench {

dp::ArpConfig small_config() {
  dp::ArpConfig c;
  c.timing = dp::VideoTimingConfig::mode(2, {160, 8, 16, 16}, {120, 2, 2, 6}, 1'400'000);
  c.memory.face_size = 64;
  c.pipeline.photon_delay_ps = 2'000'000;
  return c;
}

void fill_memories(dp::DisplayMemorySet& mem) {
  const auto& f = mem.format();
  const int S = f.face_size;
  host::load_into_memories(mem, 0, host::make_calibration_pattern(S), host::far_depth(f));
  for (int e = 0; e < mem.eyes(); ++e) {
    dp::DisplayMemoryBank& m1 = mem.bank(e, std::min(1, mem.count() - 1));
    if (mem.count() > 1) {
      for (int face : {0, 4, 5})
        for (int y = S / 4; y < 3 * S / 4; ++y)
          for (int x = S / 4; x < 3 * S / 4; ++x)
            m1.write(face, x, y, f.pack_rgb8((x * 37) & 255, (y * 11) & 255, 200), 1000 + static_cast<uint32_t>(x));
      m1.commit();
      m1.vblank();
    }
    if (mem.count() > 2) {
      dp::DisplayMemoryBank& m2 = mem.bank(e, 2);
      for (int y = 0; y < S; ++y)
        for (int x = 0; x < S; ++x)
          if ((x + y) % 2 == 0) m2.write(5, x, y, f.pack_rgb8(255, 255, 0), 1000 + static_cast<uint32_t>(y));
      m2.commit();
      m2.vblank();
    }
  }
}

dp::OrientationStream fast_turn(const dp::ArpConfig& c, int64_t first_frame, int64_t last_frame) {
  const dp::VideoTiming t(c.timing);
  const int64_t t0 = t.cycles_to_ps(t.frame_start_cycle(first_frame - 1));
  const int64_t t1 = t.cycles_to_ps(t.frame_start_cycle(last_frame + 2));
  std::vector<dp::OrientationSample> s;
  int i = 0;
  for (int64_t ps = t0; ps <= t1; ps += 1'000'000'000, ++i)
    s.push_back({ps, dp::from_yaw_pitch_roll_deg(-20.0 + 1.0 * i, 10.0 - 0.3 * i, 5.0 + 0.2 * i)});
  return dp::OrientationStream(s, "fast turn");
}

stage::TimedInputs inputs(const dp::ArpConfig& c, dp::DisplayMemorySet& mem, const dp::OrientationStream& o,
                          int64_t first_frame, int64_t frames) {
  stage::TimedInputs in;
  in.config = c;
  in.memories = &mem;
  in.orientation = &o;
  in.first_frame = first_frame;
  in.frames = frames;
  return in;
}

std::map<int64_t, CollectedFrame> run_level(scm::Fidelity f, stage::TimedInputs in, scm::TimedResult* result) {
  std::map<int64_t, CollectedFrame> out;
  in.sink = [&out](const HmdFrame& fr, const stage::FrameReport& r) { out[r.frame] = {fr, r}; };
  scm::TimedRunOptions opt;
  opt.fidelity = f;
  const scm::TimedResult res = scm::run_timed(in, opt);
  if (result) *result = res;
  return out;
}

std::map<int64_t, CollectedFrame> functional_frames(const stage::TimedInputs& in) {
  return run_level(scm::Fidelity::Functional, in);
}

}  // namespace arp::bench
