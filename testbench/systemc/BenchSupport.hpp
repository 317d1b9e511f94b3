// What the SystemC benches share: small configurations, filled memories,
// head motion, and the functional model's frames to compare against.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "rtl_model/stages/StageContext.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "rtl_model/systemc/TimedRun.hpp"

namespace arp::bench {

// 160 x 120 per eye, stereo, 4 memories of 64^2 faces: small enough for a
// detailed simulation of several frames in a test.
dp::ArpConfig small_config();

// Memory 0: the calibration pattern far away; memory 1: a nearer patch on
// some faces; memory 2: one texel-checkerboard face; memory 3: empty.
void fill_memories(dp::DisplayMemorySet& mem);

// A head turning at about 1000 deg/s about a tilted axis, sampled at 1 kHz
// from one frame before `first_frame` to after `last_frame`.
dp::OrientationStream fast_turn(const dp::ArpConfig& c, int64_t first_frame, int64_t last_frame);

// A run's inputs: frames [first_frame, first_frame + frames) of these memories and this motion.
stage::TimedInputs inputs(const dp::ArpConfig& c, dp::DisplayMemorySet& mem, const dp::OrientationStream& o,
                          int64_t first_frame, int64_t frames);

struct CollectedFrame {
  HmdFrame frame;
  stage::FrameReport report;
};

// Runs a level, keeping every frame.
std::map<int64_t, CollectedFrame> run_level(scm::Fidelity f, stage::TimedInputs in, scm::TimedResult* result = nullptr);

// The functional model's frames for the same inputs (host jobs applied at their swaps).
std::map<int64_t, CollectedFrame> functional_frames(const stage::TimedInputs& in);

}  // namespace arp::bench
