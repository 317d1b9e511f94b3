// The detailed cycle-accurate model: one SC_MODULE per stage, each with its
// own process on the pixel clock, linked by clocked FIFO channels named for
// what they carry. The host write port runs on the host clock.
//
//   VideoTimingGenerator -pixel_requests-> LensVectorTable -view_vectors->
//   OrientationMatrixUnit (TrackerInterface: orientation register)
//   -world_vectors-> CubeFaceAddressGenerator -cube_addresses->
//   DisplayMemoryBanks -texel_words-> CompositionUnit -composed_taps->
//   AntiAliasingFilter -pixel_colors-> HmdScanOut
#pragma once
#include <systemc>

#include <string>
#include <utility>
#include <vector>

#include "AntiAliasingFilter.hpp"
#include "ClockGenerator.hpp"
#include "CompositionUnit.hpp"
#include "CubeFaceAddressGenerator.hpp"
#include "DisplayMemoryBanks.hpp"
#include "FifoChannel.hpp"
#include "HmdScanOut.hpp"
#include "LensVectorTable.hpp"
#include "OrientationMatrixUnit.hpp"
#include "TrackerInterface.hpp"
#include "VideoTimingGenerator.hpp"

namespace arp::scm {

// Simulated time 0 is absolute time base_ps; the run ends at end_ps.
struct RunWindow {
  int64_t base_ps, end_ps;
  int64_t first_cycle, end_cycle;            // pixel clock
  int64_t first_host_cycle, end_host_cycle;  // host clock
};
RunWindow run_window(const cycle::PipelineKernels& k, const dp::ArpConfig& c);

class ArpPipelineTop : public sc_core::sc_module {
 public:
  ArpPipelineTop(sc_core::sc_module_name name, cycle::PipelineKernels& k, const dp::ArpConfig& c,
                 const dp::OrientationStream& o, const RunWindow& w);

  void trace(sc_core::sc_trace_file* tf);
  void stop_tracing() {
    tracing_ = false;
    k_.set_tracing(false);
  }
  std::vector<std::pair<std::string, cycle::FifoStats>> fifo_stats(int64_t end_cycle) const;
  const TrackerInterface& tracker_interface() const { return tracker; }

 private:
  bool idle() const;
  cycle::PipelineKernels& k_;
  bool tracing_ = false;
  sc_core::sc_signal<bool> pixel_clk, host_clk;
  ClockGenerator pixel_clock, host_clock;
  TrackerInterface tracker;
  FifoChannel<cycle::PixelSlot> pixel_requests;
  FifoChannel<cycle::LensToken> view_vectors;
  FifoChannel<cycle::RotatedToken> world_vectors;
  FifoChannel<cycle::AddressToken> cube_addresses;
  FifoChannel<cycle::FetchToken> texel_words;
  FifoChannel<cycle::ComposedToken> composed_taps;
  FifoChannel<cycle::ColorToken> pixel_colors;
  VideoTimingGenerator timing;
  LensVectorTable lens;
  OrientationMatrixUnit orientation;
  CubeFaceAddressGenerator address;
  DisplayMemoryBanks memories;
  CompositionUnit composition;
  AntiAliasingFilter filter;
  HmdScanOut scan_out;
};

}  // namespace arp::scm
