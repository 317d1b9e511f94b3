// What elaboration hands every stage: the run's inputs (the same for every
// fidelity level) and the pipeline's schedule. A stage keeps what it needs
// of them -- its own configuration values, a reference to the display
// memories it reads or writes, the tracker stream its register samples --
// and owns all of its state; no stage reaches into another.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "FrameReport.hpp"
#include "FrameWindows.hpp"
#include "HostWritePort.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"

namespace arp::stage {

// An injected stall: `stage` does nothing for `cycles` pixel clocks from `first_cycle`.
struct StallWindow {
  dp::Stage stage;
  int64_t first_cycle, cycles;
};

// One run's inputs, the same for every fidelity level.
struct TimedInputs {
  dp::ArpConfig config;
  dp::DisplayMemorySet* memories = nullptr;     // loaded front buffers; host jobs write the back buffers
  const dp::OrientationStream* orientation = nullptr;
  std::vector<HostWriteJob> host_jobs;
  int64_t first_frame = 0, frames = 1;
  // The frames a timed level simulates clock by clock (default: every one);
  // the run driver computes the others at the functional level (--detail).
  FrameWindows timed_frames;
  std::vector<StallWindow> stalls;              // cycle-accurate levels only
  FrameSink sink;
  // A host model updating the memories between frames: called before each
  // frame (the frame, its start in seconds) -- at the functional level before
  // rendering it, at the timed levels at the start and then in the vertical
  // blank before it (the buffer-swap clock), when no pixel is in flight.
  std::function<void(int64_t, double)> before_frame;
};

// What a stage is called: its configuration id (-1: a stage the
// configuration does not list), its block (its module's instance name), what
// its input and output carry (its ports' and FIFOs' names; nullptr: none) and
// what its three data probes show in a waveform.
struct StageInfo {
  int id;
  const char* block;
  const char* input;
  const char* output;
  std::array<const char*, 3> probes;
  constexpr dp::Stage stage() const { return static_cast<dp::Stage>(id); }
};

struct StageContext {
  const TimedInputs& in;
  dp::PipelineSchedule schedule;  // of the pipeline being elaborated (its stages' latencies)
  const dp::ArpConfig& config() const { return in.config; }
};

}  // namespace arp::stage
