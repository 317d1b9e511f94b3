#include "FunctionalFrames.hpp"

#include <utility>

namespace arp::scm {

FunctionalFrames::FunctionalFrames(const stage::TimedInputs& in, int threads, Renderer renderer)
    : in_(in), model_(in.config), renderer_(std::move(renderer)), scan_(in.config, in.first_frame, in.frames) {
  ro_.threads = threads;
  ro_.photon_times = true;
}

stage::FrameReport FunctionalFrames::render(int64_t frame) {
  if (renderer_) renderer_(frame, f_);
  else model_.render(*in_.memories, *in_.orientation, frame, f_, ro_);
  stage::FrameReport fr;
  fr.frame = frame;
  fr.pixels = static_cast<int64_t>(f_.width) * f_.height;
  // Each pixel's sample, a run of a line at a time (one run a line but with the per-pixel latch).
  for (int e = 0; e < f_.eyes; ++e)
    for (int y = 0; y < f_.height; ++y) {
      latch_segments(model_.latch_rule(), *in_.orientation, frame, e, y, f_.width, segs_);
      const int64_t* photon = &f_.photon_ps[f_.index(e, 0, y)];
      for (const LatchSegment& sg : segs_) lat_.add_run(photon + sg.x0, sg.x1 - sg.x0, (*in_.orientation)[sg.sample].time_ps);
    }
  lat_.summarise(fr);
  lat_.reset();
  const auto& t = model_.timing();
  const int64_t photon_delay = in_.config.pipeline.photon_delay_ps;
  fr.first_photon_ps = t.cycles_to_ps(t.frame_start_cycle(frame)) + photon_delay;
  fr.last_photon_ps = t.cycles_to_ps(scan_.last_slot(frame)) + photon_delay;
  return fr;
}

}  // namespace arp::scm
