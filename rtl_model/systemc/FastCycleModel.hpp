// The fast cycle-accurate model: one process per clock domain. The pixel
// clock's process evaluates every stage each cycle through the same
// cycle::PipelineKernels ticks and FIFO cores as the detailed model, then
// clocks the FIFOs -- the same cycle semantics, without a signal or process
// per stage. Two exact shortcuts, both off while a waveform is traced:
// - temporal decoupling: one activation evaluates up to kBatch cycles ahead
//   of simulated time, stopping before each vertical-blank swap cycle -- the
//   only cycle that reads another domain's state (the host's commits);
// - when the pipeline is empty and nothing is due (blanking) it jumps to the
//   next cycle where something is.
#pragma once
#include <systemc>

#include <string>
#include <utility>
#include <vector>

#include "ArpPipelineTop.hpp"
#include "TrackerInterface.hpp"
#include "rtl_model/cycle/ClockedFifo.hpp"
#include "rtl_model/cycle/PipelineKernels.hpp"

namespace arp::scm {

class FastCycleModel : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(FastCycleModel);
  FastCycleModel(sc_core::sc_module_name name, cycle::PipelineKernels& k, const dp::ArpConfig& c,
                 const dp::OrientationStream& o, const RunWindow& w);

  void trace(sc_core::sc_trace_file* tf);
  void stop_tracing() {
    tracing_ = false;
    k_.set_tracing(false);
  }
  const TrackerInterface& tracker_interface() const { return tracker; }
  std::vector<std::pair<std::string, cycle::FifoStats>> fifo_stats(int64_t end_cycle) const;
  int64_t evaluated_cycles() const { return evaluated_; }

 private:
  void pixel_domain();
  void host_domain();
  bool idle() const;
  void evaluate(int64_t c);
  static constexpr int64_t kBatch = 4096;

  cycle::PipelineKernels& k_;
  RunWindow w_;
  int64_t pixel_hz_, host_hz_;
  TrackerInterface tracker;
  cycle::ClockedFifo<cycle::PixelSlot> pixel_requests_;
  cycle::ClockedFifo<cycle::LensToken> view_vectors_;
  cycle::ClockedFifo<cycle::RotatedToken> world_vectors_;
  cycle::ClockedFifo<cycle::AddressToken> cube_addresses_;
  cycle::ClockedFifo<cycle::FetchToken> texel_words_;
  cycle::ClockedFifo<cycle::ComposedToken> composed_taps_;
  cycle::ClockedFifo<cycle::ColorToken> pixel_colors_;
  int64_t cycle_, host_cycle_;
  int64_t evaluated_ = 0;
  bool tracing_ = false, started_ = false, host_started_ = false;
};

}  // namespace arp::scm
