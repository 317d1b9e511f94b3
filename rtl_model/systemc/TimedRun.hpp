// One run of the pipeline at a chosen fidelity level, the same inputs and the
// same outputs for every level: frames with photon times (through the
// sink), per-frame latency and underflows, stage and FIFO statistics, host
// job times, and the simulator's own speed. SystemC cannot restart a
// simulation in one process: a timed level runs once per process.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "common/Parameter.hpp"
#include "rtl_model/stages/ClockedFifo.hpp"
#include "rtl_model/stages/StageContext.hpp"
#include "rtl_model/stages/StagePipe.hpp"

namespace arp::scm {

enum class Fidelity { Functional, LooselyTimed, Cycle, Detailed, Verilated };
const EnumNames<Fidelity>& fidelity_names();  // functional, lt, cycle, detailed, verilated
inline std::string to_string(Fidelity f) { return enum_name(fidelity_names(), f); }
// Also accepts rtl, the detailed level's old name.
bool parse(const std::string& s, Fidelity& out);
const char* describe(Fidelity f);

struct VcdOptions {
  std::string path;  // without ".vcd" (SystemC appends it); empty: no waveform
  std::string shown;  // the name an error gives the file (path may be a temporary's); empty: path + ".vcd"
  int64_t from_ps = std::numeric_limits<int64_t>::min();  // absolute window
  int64_t to_ps = std::numeric_limits<int64_t>::max();
  // Each stage's register data fields too; off: the control signals only
  // (clocks, handshakes, FIFO occupancy, scan position, host port,
  // orientation register), a fraction of the file and of the time.
  bool data = true;
};

struct TimedRunOptions {
  Fidelity fidelity = Fidelity::Detailed;
  VcdOptions vcd;
  std::function<void(double fraction, const std::string& what)> progress;
  int threads = 0;  // functional level only
  bool speculate = true;  // fast cycle-accurate level: FrameSpeculation (off: every stage computes every pixel)
  bool clock_gating = true;  // cycle-accurate levels: skip the clocks that would change nothing (off: every clock)
  // Polled after each scanned-out frame: true ends the run there (Ctrl-C);
  // the result then covers the frames finished.
  std::function<bool()> stop;
};

struct TimedResult {
  Fidelity fidelity = Fidelity::Detailed;
  int64_t frames = 0;     // frames scanned out (the sink saw each)
  int64_t untimed_frames = 0;  // of those, computed by the functional model between detailed windows
  bool stopped = false;   // ended early by TimedRunOptions::stop
  bool stages_measured = false, fifos_modelled = false;
  std::array<stage::StageStats, dp::kStageCount> stages{};
  std::vector<std::pair<std::string, stage::FifoStats>> fifos;
  std::vector<stage::HostJobTiming> host_jobs;
  int64_t speculated_pixels = 0, fallback_pixels = 0;  // fast level: on/off the nominal schedule
  int64_t swaps = 0, underflows = 0, late_discarded = 0, issue_stalls = 0, orientation_writes = 0;
  int64_t first_cycle = 0, end_cycle = 0;  // pixel clocks simulated: [first, end)
  int64_t evaluated_cycles = 0;            // of those, the ones the cycle-accurate levels evaluated (clock gating skips the rest)
  int64_t evaluated_host_cycles = 0;       // host clocks evaluated (gated while the write port is idle)
  int64_t issue_lead = 0, orientation_lead = 0;
  int64_t modules = 0;  // SystemC modules elaborated (the functional level: none)
  double wall_seconds = 0;
  double cycles_per_second() const {
    return wall_seconds > 0 ? static_cast<double>(end_cycle - first_cycle) / wall_seconds : 0.0;
  }
};

// Validates (validate_timed for the timed levels; InputError naming the
// setting) before anything is simulated.
TimedResult run_timed(const stage::TimedInputs& in, const TimedRunOptions& opt);

// Every SystemC simulation of a process starts here: SystemC cannot run a
// second one (std::logic_error then). Sets the 1 ps resolution and quiets SC_INFO.
void claim_simulation();

}  // namespace arp::scm
