// A run as data: everything `arpsim run` can be asked, so that the command,
// the benches and the tests describe a run the same way and hand it to a
// sim::Session. Option names in comments are the command line's; errors
// about a value name the option that set it.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "MemoryContents.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/RenderCost.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::sim {

// The host's priority rendering over a walk (--walk).
struct HostSpec {
  std::string walk;             // "gallery" or a walk file; empty: no host simulation
  std::optional<double> walk_speed;  // --speed, m/s (unset: 1, or the walk file's; 0: standing at the first point)
  bool baseline = false;        // --baseline: everything in memory 0, every frame
  std::optional<double> threshold_deg;  // --threshold-deg: overrides memory.threshold_deg (theta_t)
  // --engine-triangles, --engine-fill, --engine-setup: override host.triangles_per_s, texels_per_s, object_setup_s
  std::optional<double> engine_triangles, engine_fill, engine_setup;
  std::optional<double> region_size;  // --regions, m: overrides memory.region_size_m (0: object-level)
  std::optional<double> margin;       // --margin, m: overrides memory.region_margin_m
  bool region_cubes = false;    // --region-cubes
  bool segmentation = true;     // not --no-segmentation
  bool warp = false;            // --warp
  std::optional<double> warp_falloff;  // --warp-falloff, m (absent or 0: half a region)

  // The walk named (InputError naming --speed for a speed out of range, or the walk file's own errors).
  host::WalkPath make_walk() const;
  // theta_t in radians (InputError naming --threshold-deg outside 0 .. 90; 0 stays 0: one texel).
  static double threshold_rad(double threshold_deg);
};

// What a run writes.
struct OutputSpec {
  std::string out_dir = "run";   // --out-dir: images and photon times
  int64_t every = 1;             // --every: every Nth frame as an image (0: none)
  bool photon_times = false;     // --photon-times
  std::string report, csv, host_csv;
  std::string vcd, vcd_lines, vcd_time_us;  // --vcd NAME, window in lines or microseconds
  std::string vcd_signals = "all";          // --vcd-signals: all, or control (no register data fields)
  int64_t error_every = 10;      // --error-every (walks)
  int truth_face_size = 0;       // --truth-face-size: the truth's face size (0: the run's own)
  int truth_supersample = 1;     // --truth-supersample: the truth's pixel as the mean of N x N samples over it
  std::string tear_image, tear_at;
};

struct RunSpec {
  dp::ArpConfig config;
  std::string config_source = "configuration";  // names the configuration in errors
  std::string fidelity = "functional";           // functional, lt, cycle, detailed (rtl)
  // --detail FRAMES (repeatable): the functional level, switched to the detailed level for these
  // frames, START:END (END exclusive) or one frame, counted from the first frame.
  std::vector<std::string> detail;
  int64_t detail_warmup = 1;                     // --detail-warmup: detailed frames before each window
  double detail_speed_dps = 200;                 // --detail-speed-dps: `--detail auto` details frames turning faster
  MemoryContents memories;
  tracker::MotionSpec motion;                    // --motion ...
  std::string trace;                             // --trace FILE
  std::string live;                              // --live usb
  std::string record_live;                       // --record-live FILE: the live motion the pipeline took, as a trace
  tracker::TrackerChoice tracker;                // --device, --mag-yaw, --mag-calibrate
  HostSpec host;
  int64_t first_frame = 0, frames = 60;
  std::vector<std::string> stalls;               // --stall STAGE:CLOCK:CYCLES
  bool speculate = true;                         // not --no-speculation
  bool clock_gating = true;                      // not --no-clock-gating
  int threads = 0;
  OutputSpec out;
};

}  // namespace arp::sim
