// The live loop: head motion from a pose source (synthetic, a trace, or a
// tracker on USB), the functional model frame by frame at the display's rate
// on the wall clock, and each frame's orientation-sample -> photon latency.
// `arpsim live` presents what it computes in a window; the loop itself has
// no window and no SDL.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "LiveIntake.hpp"
#include "MemoryContents.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::sim {

struct LiveSpec {
  dp::ArpConfig config;
  std::string config_source = "the configuration";  // names it in messages (--config's file)
  MemoryContents memories;
  // Without a motion (motion.motion empty), a head shake at motion.peak: 100 deg/s unless set (`live --peak`).
  tracker::MotionSpec motion = [] {
    tracker::MotionSpec m;
    m.peak = 100;
    return m;
  }();
  std::string trace, live;     // --trace FILE, --live usb
  std::string record_live;     // --record-live FILE: the live motion the loop took, as a trace (replays with run --trace)
  tracker::TrackerChoice tracker;  // --device, --mag-yaw, --mag-calibrate
  double seconds = 0;          // 0: until stopped
  int threads = 0;
};

struct LiveFrame {
  int64_t index = 0;
  const HmdFrame* frame = nullptr;
  double render_ms = 0;
  int64_t latency_min_ps = 0, latency_median_ps = 0, latency_max_ps = 0;  // over a grid of pixels
  int64_t dropped = 0;        // frames skipped just before this one to keep up with the display's pace
  bool disconnected = false;  // the tracker is unplugged: its last pose is held
};

class LiveLoop {
 public:
  // InputError for bad options, a missing trace, or no tracker to open.
  explicit LiveLoop(const LiveSpec& spec);
  // With a live source of the caller's (spec.live empty): another device, or a test's.
  LiveLoop(const LiveSpec& spec, std::unique_ptr<tracker::PoseSource> live);
  ~LiveLoop();

  const std::string& source_name() const { return source_name_; }
  const std::string& memory_source() const { return memory_source_; }
  double refresh_hz() const { return model_.timing().refresh_hz(); }
  const dp::ArpConfig& config() const { return spec_.config; }
  // How many frames the display shows over the loop (INT64_MAX: until the caller stops).
  int64_t frames() const { return frames_; }
  // The next frame: waits for its display time (taking tracker samples meanwhile), then renders it. The
  // loop's clock starts at the first call (a window opened after the constructor does not put it behind).
  // More than a frame behind, it skips to the latest frame due (dropped, never samples): the last frame
  // is always shown.
  LiveFrame next();
  bool finished() const { return next_ >= frames_; }
  // Tracker events since the last call (unplug, replug, ...).
  std::vector<std::string> take_events();
  int64_t dropped_frames() const { return dropped_; }
  int64_t shown_frames() const { return next_ - dropped_; }
  // Orientation samples held in memory now (the window around the frame, not the whole motion).
  size_t samples_held() const { return stream_.held(); }
  // Live input: the samples taken so far, and how many were set aside: timed before the start, or stepping back
  // in time after it (LiveIntake).
  int64_t live_samples() const { return intake_ ? intake_->taken() : 0; }
  int64_t live_samples_before_start() const { return intake_ ? intake_->before_start() : 0; }
  int64_t live_samples_out_of_order() const { return intake_ ? intake_->out_of_order() : 0; }
  // Writes --record-live's trace (what was taken up to now); without a call nothing is left behind.
  void commit_record();

 private:
  LiveSpec spec_;
  FunctionalModel model_;
  int64_t frames_;
  int64_t frame_start_ps(int64_t k) const;

  std::unique_ptr<tracker::PoseSource> source_;    // a trace, or live (USB, or the caller's)
  std::unique_ptr<tracker::MotionGenerator> motion_;  // or synthetic motion, generated as the frames need it
  tracker::PoseSource* live_ = nullptr;  // source_ when it is live (USB)
  std::unique_ptr<LiveIntake> intake_;  // what is taken from live_
  std::string source_name_, memory_source_;
  dp::OrientationStream stream_;
  dp::DisplayMemorySet mem_;
  std::vector<tracker::PoseSample> got_;
  HmdFrame frame_;
  std::chrono::steady_clock::time_point wall0_;
  void start_clock();
  bool started_ = false;
  int64_t next_ = 0, dropped_ = 0;
};

}  // namespace arp::sim
