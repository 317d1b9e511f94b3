// The latency laboratory as a library: the ARP beside a conventional
// pipelined renderer (PPHIGS-like), Slats and just-in-time pixels on one
// display, one head motion and one tracker, measured the same way -- every
// sampled pixel's motion-to-photon latency and registration error, error over
// time at the screen centre (Olano et al.'s figure 9), worst error against
// rotation speed, prediction horizon and scene size (renderer overload),
// Olano's hand figures reproduced, and the simulated pendulum apparatus with
// its oscilloscope VCD. `arpsim latency` parses options into a LatencySpec.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::lab {

struct LabConfig;  // lab/ArchitectureSet.hpp

// Everything a study is asked (the option names are the command line's).
struct LatencySpec {
  dp::ArpConfig config;
  std::string config_source = "configuration";
  tracker::MotionSpec motion;
  std::string trace, out_dir = "latency", predict = "none", scene;
  bool olano = false, no_sweeps = false, no_apparatus = false;
  int64_t frames = 180;
  int grid = 8;
  double tracker_rate = 1000, horizon_ms = 0, jit_lead_us = -1;
  std::optional<double> tracker_latency_ms;  // unset: 1 ms, or 33 with --olano
  double conv_transform_ms = 8, conv_render_ms = 10, conv_copy_ms = 12, conv_rate = 2e6, triangles = 0;
  double slats_setup_ms = 1, slats_copy_ms = 3.9, slats_rate = 12000, jit_rate = 2e6;
  double walk_speed = 0, theta_deg = 0, point_distance = 2.0;
  bool no_field_sync = false;
};

// Every file the study can write into its --out-dir (each plot: its data, script, gnuplot's log and picture).
// An input of one of these names in that folder is refused before anything runs (it would be written over);
// LatencyCli.TheOutDirHoldsOnlyTheListedFiles keeps the list true to the writers.
const std::vector<std::string>& study_output_files();

// Thrown by run() when stop_requested said so: `what()` names the last step finished.
struct StudyStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class LatencyStudy {
 public:
  // InputError naming the option for a bad value, before anything is written.
  explicit LatencyStudy(LatencySpec spec);
  // Steps of the progress: architectures, sweep points, apparatus, tables.
  int64_t steps() const;
  std::function<void(const std::string&)> on_step;
  // Polled as each step finishes: true ends the study there (run() throws StudyStopped). Every file
  // written until then is whole (each is written through a temporary and a rename); table.md and
  // summary.json, written last, are not written.
  std::function<bool()> stop_requested;
  // Runs everything and writes into spec.out_dir; returns the markdown table.
  std::string run();
  // What the user should be told besides the table (plots not made, ...).
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  LabConfig lab() const;  // the settings, with the scene's triangles when --scene is given
  LatencySpec s_;
  double scene_triangles_ = -1;  // --scene's triangles per image (loaded once, by the constructor); -1: none
  std::string scene_note_;
  std::vector<std::string> notes_;
};

}  // namespace arp::lab
