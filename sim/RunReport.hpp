// What a run reports: the per-frame row (JSON for the report's "frames",
// CSV), the report's other sections built from the timed result and the host
// simulation, and the summary a command prints. The report serialises itself;
// commands only choose files.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "FrameLog.hpp"
#include "rtl_model/datapath/HmdFrame.hpp"
#include "rtl_model/systemc/TimedRun.hpp"

namespace arp::sim {

// The summary a command prints (and a test reads).
struct RunSummary {
  std::string fidelity, motion_source, memory_source;
  int64_t first_frame = 0, frames = 0;
  int64_t frames_done = 0;  // scanned out: fewer than `frames` when the run was stopped
  int stop_signal = 0;      // the signal that stopped it (SIGINT, SIGTERM), 0: ran to the end
  bool complete() const { return frames_done == frames; }
  int64_t latency_min_ps = 0, latency_median_ps = 0, latency_max_ps = 0;  // over the run (median of frame medians)
  bool cycle_accurate = false;
  int64_t underflows = 0, late_discarded = 0, swaps = 0;
  int64_t pixel_clocks = 0;
  // What was modelled (the report's footprint): SystemC modules elaborated (0 at the functional level), display
  // memory allocated at its peak and what the configuration's hardware holds, banks, texels the host stored.
  int64_t systemc_modules = 0, memory_bytes_peak = 0, memory_bytes_hardware = 0, memory_banks = 0, texels_written = 0;
  int64_t memory_bytes_hardware_tiled = 0;  // the hardware holding only the tiles drawn on (display_memory_bytes_tiled)
  int64_t memory_bytes_hardware_pooled = 0;  // with a tile pool per bank of the tiles in use at once (display_memory_bytes_pooled)
  double wall_seconds = 0;
  int64_t images = 0;
  std::string out_dir, vcd, gtkw;
  std::string detail;              // with --detail: which frames were detailed
  std::vector<std::string> notes;  // lines worth telling the user (a trace that ends early, the tear image)
  std::vector<std::string> lines() const;  // the printed summary
};

// Per-frame fingerprints: equal frames (pixels, photon times) give equal hashes,
// so levels run in different processes can be compared exactly.
std::string pixel_hash(const HmdFrame& f);
std::string photon_hash(const HmdFrame& f);
// Both, side by side on two threads unless `threads` is 1 (as --threads: 0 is every core).
struct FrameHashes {
  std::string pixels, photons;
};
FrameHashes frame_hashes(const HmdFrame& f, int threads);

std::string frame_csv_header();
// One frame's row in both forms; `first_sample`/`last_sample`: the samples its latches can take.
nlohmann::json frame_row(const stage::FrameReport& r, size_t first_sample, size_t last_sample, const std::string& pixels,
                         const std::string& photons);
std::string frame_csv_row(const stage::FrameReport& r, const std::string& pixels, const std::string& photons);

// The pipeline's part of the report: schedule, stages, FIFOs, underflows, host jobs, simulation speed.
nlohmann::json pipeline_report(const scm::TimedResult& res, const dp::ArpConfig& c, const std::string& vcd);

}  // namespace arp::sim
