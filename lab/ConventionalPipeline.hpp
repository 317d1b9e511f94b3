// Conventional pipelined frame rendering after Pixel-Planes 5's PPHIGS
// (Olano et al. 1995, figures 5-7): transform, render and copy stages for the
// stereo pair, one frame buffer between stages, a double-buffered display
// swapped in the vertical blank. The head pose is read when the transform
// starts. With field synchronisation every stage starts at a vertical blank,
// which gives PPHIGS's minimum of three fields from transform start to
// display. Render time grows with the scene (triangles / rate), which is how
// an overloaded renderer is modelled.
#pragma once
#include <vector>

#include "DisplayArchitecture.hpp"

namespace arp::lab {

struct ConventionalConfig {
  double transform_s = 0.008;   // stereo pair
  double render_s = 0.010;      // set-up part of the render stage, stereo pair
  double copy_s = 0.012;        // stereo pair
  double triangles = 0;         // scene size, added to the render stage at `triangles_per_s`
  double triangles_per_s = 2e6;
  bool field_sync = true;       // stages start at vertical blanks
  double horizon_s = 0.0;       // prediction beyond the transform start
};

class ConventionalPipeline : public DisplayArchitecture {
 public:
  // InputError naming `source` for non-positive or non-finite stage times.
  ConventionalPipeline(const DisplayRaster& d, const ConventionalConfig& c, const std::string& source);
  std::string name() const override { return "conventional"; }
  std::string description() const override;
  void schedule(int64_t first_frame, int64_t last_frame) override;
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  int64_t missed_images() const override { return dropped_; }
  double image_interval_s() const override { return interval_s_; }
  double render_stage_s() const { return c_.render_s + c_.triangles / c_.triangles_per_s; }

  struct FrameTimes {
    int64_t transform_start, transform_end, render_start, render_end, copy_start, copy_end, shown_field;
  };
  const std::vector<FrameTimes>& frames() const { return frames_; }

 private:
  int64_t sync(int64_t t) const;  // the next stage start at or after t
  const DisplayRaster& d_;
  ConventionalConfig c_;
  std::vector<FrameTimes> frames_;
  std::vector<int64_t> shown_by_field_;  // index into frames_ shown in each field, -1 none
  int64_t first_field_ = 0, dropped_ = 0;
  double interval_s_ = 0;
};

}  // namespace arp::lab
