// The orientation register and matrix unit. The tracker interface writes the
// register at each sample's time (sample-and-hold; before the first sample it
// holds the first). The unit loads its matrix (the register's quaternion as
// a signed Q1.mat_frac rotation) when a latch-point pixel enters it, reading
// the value the register had pipeline.latch_lead_cycles earlier (the
// interface's synchroniser), and rotates each view vector: three multiply-
// accumulate rows to signed Q1.rot_frac; timed.rotate_latency clocks. A
// sample written exactly at a sampling edge is caught: the read is "the last
// sample at or before t", independent of process order.
#pragma once
#include <string>

#include "RegisteredStage.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::stage {

class OrientationStage : public RegisteredStage<OrientationStage, LensToken, RotatedToken, kOrientationInfo> {
 public:
  explicit OrientationStage(const StageContext& ctx)
      : RegisteredStage(ctx),
        stream_(*ctx.in.orientation),
        timing_(ctx.config().timing),
        rot_(ctx.config().widths),
        mat_frac_(ctx.config().widths.mat_frac),
        extra_(ctx.config().pipeline.latch_lead_cycles) {}

  template <class InFifo, class OutFifo>
  void tick(int64_t cycle, InFifo& in, OutFifo& out) {
    tick_with(cycle, in, out, [this, cycle](const LensToken& t, RotatedToken& o) { compute(t, cycle, o); });
  }
  // A pixel entering the unit at `cycle`: the latch, then the rotation.
  void compute(const LensToken& t, int64_t cycle, RotatedToken& o) {
    latch(t.slot, cycle);
    rotate(t, matrix, sample, o);
  }
  // The register's sample at pixel clock `cycle`.
  size_t register_sample(int64_t cycle) const { return dp::register_sample(stream_, timing_, cycle); }
  // Loads the matrix if `s` is a latch point (or nothing is loaded yet).
  void latch(const PixelSlot& s, int64_t cycle) {
    if (!s.latch && loaded_) return;
    const size_t i = register_sample(cycle - extra_);
    if (!loaded_ || i != sample) {
      matrix = matrix_of(i);
      sample = static_cast<uint32_t>(i);
    }
    loaded_ = true;
    ++latches;
  }
  void rotate(const LensToken& in, const dp::Mat3q& m, uint32_t s, RotatedToken& t) const {
    t.slot = in.slot;
    t.sample = s;  // the register's, not the input's
    for (int k = 0; k < in.slot.eye_count; ++k) t.world[k] = dp::rotate(m, in.view[k], rot_);
  }
  dp::Mat3q matrix_of(size_t sample_index) const { return dp::quantise_rotation(stream_[sample_index].q, mat_frac_); }
  const dp::OrientationStream& stream() const { return stream_; }
  // Waveform: the matrix register and the tracker sample it holds.
  template <class Fn>
  void for_each_own_probe(Fn&& fn) const {
    fn("matrix_sample", sample);
    for (int i = 0; i < 9; ++i) fn("matrix_" + std::to_string(i / 3) + std::to_string(i % 3), matrix.m[i]);
  }

  // Traced: the matrix register and which tracker sample it holds.
  dp::Mat3q matrix{};
  uint32_t sample = 0;
  int64_t latches = 0;

 private:
  const dp::OrientationStream& stream_;
  dp::VideoTiming timing_;
  dp::RotateParams rot_;
  int mat_frac_;
  int64_t extra_;
  bool loaded_ = false;
};

}  // namespace arp::stage
