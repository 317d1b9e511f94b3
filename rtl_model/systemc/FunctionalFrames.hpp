// Frames at the functional level, reported as every level reports its
// frames: the image with photon times computed from the schedule, and its
// stage::FrameReport (each pixel's latched sample -> photon latency, the
// frame's first and last photon). The functional and verilated levels are a
// loop over it; a run with detailed windows (--detail) computes the frames
// between its windows with it.
#pragma once
#include <cstdint>
#include <functional>

#include "rtl_model/functional/FunctionalModel.hpp"
#include "rtl_model/stages/FrameReport.hpp"
#include "rtl_model/stages/LatencyRuns.hpp"
#include "rtl_model/stages/ScanTiming.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

class FunctionalFrames {
 public:
  // Renders a frame in place of the functional model (the verilated level's RTL).
  using Renderer = std::function<void(int64_t frame, HmdFrame& out)>;
  // Keeps references to the inputs' memories and orientation stream.
  FunctionalFrames(const stage::TimedInputs& in, int threads, Renderer renderer = {});

  // Frame `frame` as the memories and the stream hold it now, into frame(), and its report.
  stage::FrameReport render(int64_t frame);
  const HmdFrame& frame() const { return f_; }
  const FunctionalModel& model() const { return model_; }

 private:
  const stage::TimedInputs& in_;
  FunctionalModel model_;
  Renderer renderer_;
  stage::ScanTiming scan_;
  RenderOptions ro_;
  HmdFrame f_;
  stage::LatencyRuns lat_;
  std::vector<LatchSegment> segs_;
};

}  // namespace arp::scm
