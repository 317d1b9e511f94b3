#include "ScanOutStage.hpp"

namespace arp::cycle {

ScanOutStage::ScanOutStage(const StageArithmetic& a, const ScanTiming& scan, const dp::OrientationStream& stream,
                           FrameSink sink)
    : arith_(a),
      scan_(scan),
      stream_(stream),
      sink_(std::move(sink)),
      latency_(a.config().timed.stage[static_cast<size_t>(dp::Stage::ScanOut)].latency_cycles),
      photon_delay_(a.config().pipeline.photon_delay_ps),
      delay_(static_cast<size_t>(latency_)),
      bad_(underflow_color(a.config().pipeline.display_bits)),
      clock_(a.config().timing.pixel_clock_hz) {
  frame_.resize(a.lens_table().width(), a.lens_table().height(), a.lens_table().eyes(), true);
  frame_.display_bits = a.config().pipeline.display_bits;
  frame_.frame_index = scan.first_frame();
}

void ScanOutStage::show(const ColorToken& t, int64_t slot) {
  const int64_t photon = clock_.ps(slot) + photon_delay_;
  const int64_t sample_ps = stream_[t.sample].time_ps;
  lat_.add(photon, sample_ps, t.slot.eye_count);
  const HmdFrame* spec = t.slot.on_schedule ? &spec_->frame(t.slot.frame, -1) : nullptr;
  for (int k = 0; k < t.slot.eye_count; ++k) {
    const size_t i = frame_.index(t.slot.eye_first + k, t.slot.x, t.slot.y);
    frame_.pixels[i] = spec ? spec->pixels[i] : arith_.display(t.color[k]);
    frame_.photon_ps[i] = photon;
  }
  Shown& d = delay_[ring(slot)];
  d.valid = true;
  d.rgb = frame_.pixels[frame_.index(t.slot.eye_first, t.slot.x, t.slot.y)];
}

void ScanOutStage::underflow(const PixelSlot& s) {
  const int64_t photon = clock_.ps(s.slot_cycle) + photon_delay_;
  for (int k = 0; k < s.eye_count; ++k) {
    const size_t i = frame_.index(s.eye_first + k, s.x, s.y);
    frame_.pixels[i] = bad_;
    frame_.photon_ps[i] = photon;
  }
  ++underflows_;
  ++underflows_total_;
  underflow_count = underflows_total_;
  Shown& d = delay_[ring(s.slot_cycle)];
  d.valid = true;
  d.rgb = bad_;
}

void ScanOutStage::finish_frame(int64_t frame) {
  FrameReport r;
  r.frame = frame;
  r.pixels = static_cast<int64_t>(frame_.width) * frame_.height;
  r.underflows = underflows_;
  r.late_discarded = late_;
  const auto& t = scan_.timing();
  r.first_photon_ps = t.cycles_to_ps(t.frame_start_cycle(frame)) + photon_delay_;
  r.last_photon_ps = t.cycles_to_ps(scan_.last_slot(frame)) + photon_delay_;
  lat_.summarise(r);
  frame_.frame_index = frame;
  if (sink_) sink_(frame_, r);
  if (spec_) spec_->retire_before(frame + 1);
  lat_.reset();
  underflows_ = late_ = 0;
}

}  // namespace arp::cycle
