// The virtual oscilloscope of the latency apparatus: a SystemC module that
// samples the pendulum photodiode, and each architecture's render-start
// signal and screen photodiode, at a fixed sample rate, drives them onto
// signals traced to a VCD (sc_trace), and records the edges it sees -- the
// only thing the external measurement is allowed to use.
#pragma once
#include <string>
#include <vector>

#include "PendulumApparatus.hpp"

namespace arp::apparatus {

struct ScopeRun {
  int64_t start_ps = 0, end_ps = 0;
  double render_pulse_s = 50e-6;  // the D/A converter's pulse width
  std::string vcd_path;           // empty: no waveform (the path gets ".vcd" from SystemC; give it without)
  std::string vcd_shown;          // the name an error gives the waveform (vcd_path may be a temporary's)
};

// Runs the simulation (one per process: scm::claim_simulation). Channel names
// become signal names (characters other than letters and digits -> '_').
ScopeEdges run_oscilloscope(const PendulumSpec& p, const std::vector<ChannelEvents>& channels, const ScopeRun& run);

}  // namespace arp::apparatus
