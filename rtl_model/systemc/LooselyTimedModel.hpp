// The loosely timed model: one process whose quantum is a scanline. At the
// time a line's first pixel would be issued it computes the whole line
// through the same stage objects' arithmetic (rtl_model/stages), latching
// the orientation for each pixel at the cycle the schedule says it enters the
// orientation matrix unit, and annotates each pixel with its scan-out time.
// Host writes are applied whole at the vertical blank that swaps them. No
// FIFOs or stalls are modelled: its frames and photon times equal the
// cycle-accurate models' whenever those do not stall (tested), and it cannot
// show underflows.
#pragma once
#include <systemc>

#include <memory>
#include <utility>
#include <vector>

#include "ArpPipelineTop.hpp"
#include "TrackerInterface.hpp"
#include "rtl_model/stages/AddressStage.hpp"
#include "rtl_model/stages/CompositionStage.hpp"
#include "rtl_model/stages/FilterStage.hpp"
#include "rtl_model/stages/HostWritePort.hpp"
#include "rtl_model/stages/LensVectorStage.hpp"
#include "rtl_model/stages/MemoryReadStage.hpp"
#include "rtl_model/stages/OrientationStage.hpp"
#include "rtl_model/stages/VideoTimingStage.hpp"

namespace arp::scm {

class LooselyTimedModel : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(LooselyTimedModel);
  LooselyTimedModel(sc_core::sc_module_name name, const stage::TimedInputs& in);

  const RunWindow& window() const { return w_; }
  void trace(sc_core::sc_trace_file* tf);
  const TrackerInterface& tracker_interface() const { return tracker; }
  const std::vector<stage::HostJobTiming>& host_timings() const { return host_.timings(); }
  int64_t swaps() const { return swaps_; }
  int64_t quanta() const { return quanta_; }

 private:
  void run();
  void line(int64_t frame, int y);
  void resume_at(int64_t c);
  std::vector<std::pair<int64_t, int>> lines_;  // (line start offset in the frame, y), scan order
  size_t next_line_ = 0;
  int64_t frame_no_ = 0;

  const stage::TimedInputs& in_;
  stage::StageContext ctx_;
  stage::VideoTimingStage timing_;
  RunWindow w_;
  // The stages whose arithmetic a line goes through, in order.
  stage::LensVectorStage lens_;
  stage::OrientationStage orientation_;
  stage::AddressStage address_;
  stage::MemoryReadStage memories_;
  stage::CompositionStage composition_;
  stage::FilterStage filter_;
  dp::HmdScanOut panel_;  // memory colour -> the panel's
  stage::PlannedHostWrites host_;
  TrackerInterface tracker;
  struct Tokens {  // one pixel's tokens, stage by stage
    stage::LensToken lens;
    stage::RotatedToken rotated;
    stage::AddressToken address;
    stage::FetchToken fetch;
    stage::ComposedToken composed;
    stage::ColorToken color;
  };
  std::unique_ptr<Tokens> tokens_;
  int64_t rotate_to_scanout_;
  HmdFrame frame_;
  stage::LatencyCollector lat_;
  int64_t swaps_ = 0, quanta_ = 0;
  // Traced.
  int64_t quantum_frame_ = 0;
  int32_t quantum_line_ = 0;
};

}  // namespace arp::scm
