// Synthetic head motion from the command line, shared by `tracker synth`
// (which writes it as a trace) and `run` (which drives the pipeline with it).
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "tracker/PoseSample.hpp"

namespace arp::app {

struct MotionOptions {
  std::string motion, axis = "0,1,0";
  double rate = 100.0, peak = 200.0, frequency = 1.0, amplitude = 30.0, period = 2.0;
  double hz = 1000.0, noise = 0.0;
  uint64_t seed = 1;
  // `required`: --motion must be given.
  void add_to(CLI::App& cmd, bool required);
  bool given() const { return !motion.empty(); }
  // Samples over [start_s, start_s + seconds]; InputError naming the option on bad values.
  std::vector<tracker::PoseSample> make(double start_s, double seconds) const;
};

}  // namespace arp::app
