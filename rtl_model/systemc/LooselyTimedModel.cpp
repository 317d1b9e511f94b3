#include "LooselyTimedModel.hpp"

#include <algorithm>
#include <string>

#include "ClockGenerator.hpp"

namespace arp::scm {

using namespace sc_core;

LooselyTimedModel::LooselyTimedModel(sc_module_name name, const stage::TimedInputs& in)
    : sc_module(name),
      in_(in),
      ctx_{in, dp::PipelineSchedule(in.config)},
      timing_(ctx_),
      w_(run_window(timing_, in.config)),
      lens_(ctx_),
      orientation_(ctx_),
      address_(ctx_),
      memories_(ctx_),
      composition_(ctx_),
      filter_(ctx_),
      panel_(dp::MemoryFormat(in.config.memory), in.config.pipeline),
      host_(in.config, in.host_jobs),
      tracker("tracker_interface", *in.orientation, w_.base_ps, w_.end_ps),
      tokens_(std::make_unique<Tokens>()),
      rotate_to_scanout_(ctx_.schedule.stage_to_scanout(dp::Stage::Rotate)) {
  const auto& tc = in.config.timing;
  frame_.resize(tc.h_active, tc.v_active, tc.eyes, true);
  frame_.display_bits = in.config.pipeline.display_bits;
  SC_METHOD(run);
}

// Asks to run again at pixel clock c (now, if c has passed).
void LooselyTimedModel::resume_at(int64_t c) {
  const sc_time t = sim_time(timing_.scan().timing().cycles_to_ps(c), w_.base_ps);
  next_trigger(t > sc_time_stamp() ? t - sc_time_stamp() : SC_ZERO_TIME);
}

void LooselyTimedModel::line(int64_t frame, int y) {
  const auto& t = timing_.scan().timing();
  const auto& tc = in_.config.timing;
  const int64_t delay = in_.config.pipeline.photon_delay_ps;
  const int sbs = tc.eye_scan == dp::EyeScan::SideBySide ? tc.eyes : 1;
  for (int e0 = 0; e0 < sbs; ++e0)
    for (int x = 0; x < tc.h_active; ++x) {
      const int64_t slot_cycle = t.pixel_cycle(frame, e0, x, y);
      stage::PixelSlot s;
      timing_.scan().decode(slot_cycle, s);
      Tokens& tok = *tokens_;
      lens_.compute(s, tok.lens);
      orientation_.compute(tok.lens, slot_cycle - rotate_to_scanout_, tok.rotated);
      address_.compute(tok.rotated, tok.address);
      memories_.compute(tok.address, tok.fetch);
      composition_.compute(tok.fetch, tok.composed);
      filter_.compute(tok.composed, tok.color);
      const stage::ColorToken& c = tok.color;
      const int64_t photon = t.cycles_to_ps(slot_cycle) + delay;
      const int64_t sample_ps = (*in_.orientation)[c.sample].time_ps;
      lat_.add(photon, sample_ps, s.eye_count);
      for (int k = 0; k < s.eye_count; ++k) {
        const size_t i = frame_.index(s.eye_first + k, s.x, s.y);
        frame_.pixels[i] = panel_.to_display(c.color[k]);
        frame_.photon_ps[i] = photon;
      }
    }
}

// One activation per quantum: a scanline, or the vertical blank after a
// frame's last line. (A method, not a thread: SystemC's thread stacks are
// coroutines the address sanitizer's leak checker cannot walk.)
void LooselyTimedModel::run() {
  const auto& t = timing_.scan().timing();
  const auto& sched = ctx_.schedule;
  const int64_t lead = sched.issue_lead();
  if (lines_.empty()) {  // first activation: the lines in scan order, then wait for the first
    const auto& tc = in_.config.timing;
    for (int y = 0; y < tc.v_active; ++y) lines_.push_back({t.line_start_cycle(0, y), y});
    std::sort(lines_.begin(), lines_.end());
    frame_no_ = timing_.scan().first_frame();
    next_line_ = 0;
    resume_at(t.frame_start_cycle(frame_no_) + lines_[0].first - lead);
    return;
  }
  if (frame_no_ >= timing_.scan().end_frame()) return;
  if (next_line_ < lines_.size()) {
    const int y = lines_[next_line_].second;
    quantum_frame_ = frame_no_;
    quantum_line_ = y;
    ++quanta_;
    line(frame_no_, y);
    ++next_line_;
    resume_at(next_line_ < lines_.size() ? t.frame_start_cycle(frame_no_) + lines_[next_line_].first - lead
                                         : sched.swap_cycle(frame_no_));
    return;
  }
  // The vertical blank after the frame: host writes land, buffers swap, the frame is out.
  const int64_t sw = sched.swap_cycle(frame_no_);
  swaps_ += host_.at_vertical_blank(t.cycles_to_ps(sw), *in_.memories);
  if (in_.before_frame && frame_no_ + 1 < timing_.scan().end_frame())
    in_.before_frame(frame_no_ + 1, t.frame_start_s(frame_no_ + 1));
  stage::FrameReport r;
  r.frame = frame_no_;
  r.pixels = static_cast<int64_t>(frame_.width) * frame_.height;
  r.first_photon_ps = t.cycles_to_ps(t.frame_start_cycle(frame_no_)) + in_.config.pipeline.photon_delay_ps;
  r.last_photon_ps = t.cycles_to_ps(timing_.scan().last_slot(frame_no_)) + in_.config.pipeline.photon_delay_ps;
  lat_.summarise(r);
  frame_.frame_index = frame_no_;
  if (in_.sink) in_.sink(frame_, r);
  lat_.reset();
  ++frame_no_;
  next_line_ = 0;
  if (frame_no_ < timing_.scan().end_frame()) resume_at(t.frame_start_cycle(frame_no_) + lines_[0].first - lead);
}

void LooselyTimedModel::trace(sc_trace_file* tf) {
  const std::string n = name();
  sc_trace(tf, quantum_frame_, n + ".quantum_frame");
  sc_trace(tf, quantum_line_, n + ".quantum_line");
  sc_trace(tf, orientation_.sample, n + ".matrix_sample");
  tracker.trace(tf);
}

}  // namespace arp::scm
