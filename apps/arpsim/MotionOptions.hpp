// Synthetic head motion on the command line: the options of
// tracker::MotionSpec, shared by `tracker synth`, `run`, `latency` and `live`.
#pragma once
#include <CLI/CLI.hpp>

#include "tracker/PoseSource.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::app {

// `required`: --motion must be given. `shape_needs_motion`: --axis, --rate, --peak, --frequency, --amplitude,
// --period, --hz, --noise and --seed are refused without --motion (run, plan: no --motion is no motion); where a default motion plays
// without one (latency, live: a shake) they shape that.
void add_motion_options(CLI::App& cmd, tracker::MotionSpec& m, bool required, bool shape_needs_motion = true);
// --device SERIAL|BUS:ADDR: which USB tracker, and --mag-yaw GAIN: its magnetometer's yaw correction
// (tracker record, --live usb).
void add_device_option(CLI::App& cmd, tracker::TrackerChoice& choice);
// --record-live FILE (run, live).
void add_record_live_option(CLI::App& cmd, std::string& path);

}  // namespace arp::app
