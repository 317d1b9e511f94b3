#include "ScanOutStage.hpp"

namespace arp::stage {

ScanOutStage::ScanOutStage(const StageContext& ctx)
    : scan_(ctx.config(), ctx.in.first_frame, ctx.in.frames, ctx.in.timed_frames),
      panel_(dp::MemoryFormat(ctx.config().memory), ctx.config().pipeline),
      stream_(*ctx.in.orientation),
      sink_(ctx.in.sink),
      latency_(ctx.config().timed.stage[static_cast<size_t>(dp::Stage::ScanOut)].latency_cycles),
      photon_delay_(ctx.config().pipeline.photon_delay_ps),
      delay_(static_cast<size_t>(latency_)),
      bad_(underflow_color(ctx.config().pipeline.display_bits)),
      clock_(ctx.config().timing.pixel_clock_hz) {
  const auto& tc = ctx.config().timing;
  frame_.resize(tc.h_active, tc.v_active, tc.eyes, true);
  frame_.display_bits = ctx.config().pipeline.display_bits;
  frame_.frame_index = scan_.first_frame();
}

void ScanOutStage::show(const ColorToken& t, int64_t slot) {
  const int64_t photon = clock_.ps(slot) + photon_delay_;
  const int64_t sample_ps = stream_[t.sample].time_ps;
  lat_.add(photon, sample_ps, t.slot.eye_count);
  const HmdFrame* spec = t.slot.on_schedule ? &prerendered_->frame(t.slot.frame) : nullptr;
  for (int k = 0; k < t.slot.eye_count; ++k) {
    const size_t i = frame_.index(t.slot.eye_first + k, t.slot.x, t.slot.y);
    frame_.pixels[i] = spec ? spec->pixels[i] : panel_.to_display(t.color[k]);
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
  if (prerendered_) prerendered_->retire_before(frame + 1);
  lat_.reset();
  underflows_ = late_ = 0;
}

}  // namespace arp::stage
