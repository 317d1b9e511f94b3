// Orientation matrix unit: the orientation register (a 3x3 rotation, head
// frame -> world/cube frame, signed Q1.mat_frac), the latch policy that picks
// which tracker sample applies to which pixel, and the fixed-point
// matrix-times-vector of the lens direction.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ArpConfig.hpp"
#include "FixedPoint.hpp"
#include "LensVectorTable.hpp"
#include "VideoTiming.hpp"

namespace arp::dp {

struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
};

// Unit quaternion from any non-zero finite one; InputError naming `source` otherwise.
Quat normalised(const Quat& q, const std::string& source);

// Yaw about +y (positive turns left), then pitch about +x (positive looks up),
// then roll about +z (positive tilts the head to the left): q = yaw * pitch * roll.
Quat from_yaw_pitch_roll_deg(double yaw, double pitch, double roll);

struct Mat3q {
  int32_t m[9];  // row-major
};

// The value the tracker interface writes into the orientation register:
// R(q) rounded half-even to Q1.mat_frac, saturated to mat_frac+2 bits.
Mat3q quantise_rotation(const Quat& unit_q, int mat_frac);

struct RotateParams {
  RoundShift shift;   // from Q(mat_frac+vec_frac) products to Q(rot_frac)
  SignedRange out;    // rot_frac + 2 bits
  RotateParams() = default;
  RotateParams(const DatapathWidths& w)
      : shift(w.mat_frac + w.vec_frac - w.rot_frac, w.rot_rounding), out(w.rot_frac + 2) {}
};

// Three multiply-accumulate rows in accumulators of type I: int64_t holds any valid widths (<= 30 x
// 30-bit products, three terms); int32_t the configurations rotate_fits_int32 admits.
template <class I>
inline Vec3q rotate_as(const Mat3q& M, const Vec3q& v, const RotateParams& p) {
  const I sx = I{M.m[0]} * v.x + I{M.m[1]} * v.y + I{M.m[2]} * v.z;
  const I sy = I{M.m[3]} * v.x + I{M.m[4]} * v.y + I{M.m[5]} * v.z;
  const I sz = I{M.m[6]} * v.x + I{M.m[7]} * v.y + I{M.m[8]} * v.z;
  return {static_cast<int32_t>(p.out.clamp_as<I>(p.shift.apply_as<I>(sx))),
          static_cast<int32_t>(p.out.clamp_as<I>(p.shift.apply_as<I>(sy))),
          static_cast<int32_t>(p.out.clamp_as<I>(p.shift.apply_as<I>(sz)))};
}
inline Vec3q rotate(const Mat3q& M, const Vec3q& v, const RotateParams& p) { return rotate_as<int64_t>(M, v, p); }

// Whether rotate_as<int32_t> gives rotate's result for every matrix the orientation register can hold
// (quantise_rotation: mat_frac + 2 bits) and every lens vector whose components are at most max_vec in
// magnitude: the three products' sum, shifted and rounded, and the output range all fit 32 bits.
bool rotate_fits_int32(const DatapathWidths& w, int64_t max_vec);

// A timed orientation from the tracker.
struct OrientationSample {
  int64_t time_ps = 0;
  Quat q;
};

// The orientation register's input: samples in non-decreasing time order.
// Sample-and-hold: at time t the register holds the last sample at or before
// t; before the first sample it holds the first (its reset value).
class OrientationStream {
 public:
  OrientationStream() = default;
  // Validates (finite, non-zero, time order) and normalises; InputError names `source` and the sample index.
  OrientationStream(std::vector<OrientationSample> samples, const std::string& source);
  static OrientationStream constant(const Quat& q);
  // Live input: more samples, validated like the first (none earlier than the last one held).
  void append(const std::vector<OrientationSample>& more, const std::string& source);

  // Indices count from the stream's first sample ever, also after discard_before.
  size_t size() const { return base_ + samples_.size(); }
  size_t held() const { return samples_.size(); }  // in memory now: what discard_before left
  const OrientationSample& operator[](size_t i) const { return samples_[i - base_]; }
  size_t index_at(int64_t t_ps) const;
  // A long run's window: drops the samples no reader needs any more -- those
  // before `t_ps` but the last one at or before it (the register's value at
  // `t_ps`). Reading a time before the window is then a std::logic_error.
  void discard_before(int64_t t_ps);

 private:
  std::vector<OrientationSample> samples_;
  size_t base_ = 0;  // index of samples_[0]
};

// The orientation register as a reader sees it at pixel clock `cycle`: the
// sample-and-hold of the tracker stream (the last sample at or before the clock).
size_t register_sample(const OrientationStream& s, const VideoTiming& t, int64_t cycle);

// The latch rule: the one place that says which tracker sample a pixel sees.
// The orientation matrix unit reloads its matrix at latch points -- the first
// pixel of each frame, field or scanline, or every pixel -- reading the
// register `lead` pixel clocks before the latch point's scan-out slot; every
// pixel up to the next latch point uses that matrix. The lead is the
// pipeline's (PipelineSchedule::orientation_lead) for every fidelity level, so
// all of them latch the same sample; the timed levels, whose latch point may
// be late after a stall, read the register at the cycle it really enters the
// unit (minus pipeline.latch_lead_cycles) through register_sample.
class LatchRule {
 public:
  LatchRule(const VideoTiming& t, LatchPolicy policy, int64_t lead_cycles);
  // The configuration's policy and pipeline lead.
  explicit LatchRule(const ArpConfig& c);

  LatchPolicy policy() const { return policy_; }
  int64_t lead_cycles() const { return lead_; }

  // Whether pixel (eye, x, y) is a latch point. (In a lock-step stereo slot
  // both eyes share eye 0's answer; a side-by-side line starts at eye 0.)
  bool is_latch_point(int eye, int x, int y) const {
    const bool line_start = x == 0 && eye == 0;
    switch (policy_) {
      case LatchPolicy::PerFrame: return line_start && y == 0;
      case LatchPolicy::PerField: return line_start && y < fields_;
      case LatchPolicy::PerScanline: return line_start;
      case LatchPolicy::PerPixel: return true;
    }
    return true;
  }
  // The pixel clock at which the register is read for pixel (frame, eye, x, y).
  int64_t read_cycle(int64_t frame, int eye, int x, int y) const;
  // The sample pixel (frame, eye, x, y) sees.
  size_t sample(const OrientationStream& s, int64_t frame, int eye, int x, int y) const {
    return register_sample(s, timing_, read_cycle(frame, eye, x, y));
  }
  // The first and last sample frame `frame`'s pixels can see (its first latch
  // to the next frame's first latch).
  std::pair<size_t, size_t> frame_samples(const OrientationStream& s, int64_t frame) const {
    return {register_sample(s, timing_, timing_.frame_start_cycle(frame) - lead_),
            register_sample(s, timing_, timing_.frame_start_cycle(frame + 1) - lead_)};
  }

 private:
  VideoTiming timing_;
  LatchPolicy policy_;
  int64_t lead_;
  int fields_;
};

}  // namespace arp::dp
