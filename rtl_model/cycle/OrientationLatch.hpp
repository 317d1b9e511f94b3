// The orientation register and its latch. The tracker interface writes the
// register at each sample's time (sample-and-hold; before the first sample it
// holds the first). The orientation matrix unit loads its matrix from the
// register when a latch-point pixel enters it, reading the value the
// register had pipeline.latch_lead_cycles earlier (the interface's
// synchroniser). A sample written exactly at a sampling edge is caught: the
// read is "the last sample at or before t", independent of process order.
#pragma once
#include <cstdint>

#include "StageArithmetic.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::cycle {

class OrientationLatch {
 public:
  OrientationLatch(const StageArithmetic& a, const dp::OrientationStream& s)
      : arith_(a), stream_(s), timing_(a.config().timing), extra_(a.config().pipeline.latch_lead_cycles) {}

  // The register's sample at pixel clock `cycle`.
  size_t register_sample(int64_t cycle) const { return dp::register_sample(stream_, timing_, cycle); }

  // A pixel entering the unit at `cycle`: loads the matrix if it is a latch point.
  void on_pixel(const PixelSlot& s, int64_t cycle) {
    if (!s.latch && loaded_) return;
    const size_t i = register_sample(cycle - extra_);
    if (!loaded_ || i != sample) {
      matrix = arith_.matrix(stream_[i].q);
      sample = static_cast<uint32_t>(i);
    }
    loaded_ = true;
    ++latches;
  }

  const dp::OrientationStream& stream() const { return stream_; }

  // Traced: the matrix register and which tracker sample it holds.
  dp::Mat3q matrix{};
  uint32_t sample = 0;
  int64_t latches = 0;

 private:
  const StageArithmetic& arith_;
  const dp::OrientationStream& stream_;
  dp::VideoTiming timing_;
  int64_t extra_;
  bool loaded_ = false;
};

}  // namespace arp::cycle
