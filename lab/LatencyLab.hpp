// The latency laboratory's measurements, the same for every architecture on
// one timeline: each displayed pixel's motion-to-photon latency (photon time
// minus the sample time of the tracker report it was computed from), and its
// registration error -- the angle, in display pixels, between where the pose
// it was computed with put a world point and where the true head pose at its
// photon time would put it. When the head also moves (the motion has
// positions), the world points are point_distance_m from where each image
// was drawn from, so translation shows as parallax. Sampled on a pixel grid every refresh, plus the
// screen centre (Olano et al.'s figure 9 follows the centre).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "DisplayArchitecture.hpp"
#include "TrackerFeed.hpp"

namespace arp::lab {

struct LabSettings {
  int64_t first_frame = 0, frames = 120;
  int grid_step = 8;  // sample every Nth pixel and line (plus the last ones and the centre)
  Prediction prediction = Prediction::None;
  double point_distance_m = 2.0;  // the tracked world points' distance (matters only when the head moves, not just turns)
};

struct FramePoint {
  double time_s = 0;            // photon time of the screen centre
  bool shown = false;           // the architecture had an image
  double centre_error_px = 0;
  double max_error_px = 0;      // over the grid
  double mean_error_px = 0;
  double centre_latency_ms = 0;
};

struct Distribution {
  double min = 0, p50 = 0, p99 = 0, max = 0, mean = 0;
  int64_t count = 0;
};
Distribution distribution(std::vector<double> v);

struct ArchitectureResult {
  std::string name, description;
  std::vector<FramePoint> frames;
  std::vector<double> latency_ms;        // every sampled pixel of every refresh with an image
  Distribution position_age_ms;          // photon - the time of the position drawn from (when the head moves)
  Distribution latency, centre_error, max_error;  // max_error: per-frame worst over the grid
  int64_t missed_images = 0, frames_without_image = 0;
  double image_interval_s = 0;
};

// Error of one pixel, degrees of arc (the lab converts with DisplayRaster::pixels_per_degree).
double pixel_error_deg(const DisplayRaster& d, const TrackerFeed& feed, const PoseUse& u, Prediction p, int64_t photon_ps,
                       int x, int y, double point_distance_m = 2.0);

ArchitectureResult measure(DisplayArchitecture& a, const DisplayRaster& d, const TrackerFeed& feed, const LabSettings& s);

}  // namespace arp::lab
