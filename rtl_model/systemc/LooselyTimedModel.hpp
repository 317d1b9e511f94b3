// The loosely timed model: one process whose quantum is a scanline. At the
// time a line's first pixel would be issued it computes the whole line
// through the same stage arithmetic, latching the orientation for each pixel
// at the cycle the schedule says it enters the orientation matrix unit, and
// annotates each pixel with its scan-out time. Host writes are applied whole
// at the vertical blank that swaps them. No FIFOs or stalls are modelled:
// its frames and photon times equal the cycle-accurate models' whenever those
// do not stall (tested), and it cannot show underflows.
#pragma once
#include <systemc>

#include <memory>
#include <utility>
#include <vector>

#include "ArpPipelineTop.hpp"
#include "TrackerInterface.hpp"
#include "rtl_model/cycle/FrameReport.hpp"
#include "rtl_model/cycle/HostWritePort.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class LooselyTimedModel : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(LooselyTimedModel);
  LooselyTimedModel(sc_core::sc_module_name name, const cycle::TimedInputs& in, const RunWindow& w);

  void trace(sc_core::sc_trace_file* tf);
  const TrackerInterface& tracker_interface() const { return tracker; }
  const std::vector<cycle::HostJobTiming>& host_timings() const { return host_.timings(); }
  int64_t swaps() const { return swaps_; }
  int64_t quanta() const { return quanta_; }

 private:
  void run();
  void line(int64_t frame, int y);
  void resume_at(int64_t c);
  std::vector<std::pair<int64_t, int>> lines_;  // (line start offset in the frame, y), scan order
  size_t next_line_ = 0;
  int64_t frame_no_ = 0;

  const cycle::TimedInputs& in_;
  RunWindow w_;
  cycle::StageArithmetic arith_;
  cycle::ScanTiming scan_;
  cycle::OrientationLatch latch_;
  cycle::PlannedHostWrites host_;
  TrackerInterface tracker;
  struct Tokens {  // one pixel's tokens, stage by stage
    cycle::LensToken lens;
    cycle::RotatedToken rotated;
    cycle::AddressToken address;
    cycle::FetchToken fetch;
    cycle::ComposedToken composed;
    cycle::ColorToken color;
  };
  std::unique_ptr<Tokens> tokens_;
  int64_t rotate_to_scanout_;
  HmdFrame frame_;
  cycle::LatencyCollector lat_;
  int64_t swaps_ = 0, quanta_ = 0;
  // Traced.
  int64_t quantum_frame_ = 0;
  int32_t quantum_line_ = 0;
};

}  // namespace arp::scm
