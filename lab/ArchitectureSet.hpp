// The laboratory's line-up, built from one set of settings so every
// architecture sees the same display, tracker, prediction and scene:
// conventional, Slats, just-in-time pixels (per scanline, two per field, per
// pixel) and the ARP latched per frame, per scanline and per pixel.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "ArpOrientationPath.hpp"
#include "ConventionalPipeline.hpp"
#include "JustInTimePixels.hpp"
#include "SlatsPipeline.hpp"

namespace arp::lab {

struct LabConfig {
  ConventionalConfig conventional;
  SlatsConfig slats;
  double jit_lead_s = -1;   // -1: one line
  double jit_triangles_per_s = 2e6;
  double horizon_s = 0;     // prediction beyond the compute time (conventional, Slats, ARP)
  double triangles = 0;     // the scene, for the renderers that draw it per image
  double arp_threshold_rad = 0;   // the ARP's priority-rendering θt (0: one texel)
  double point_distance_m = 2.0;  // the tracked points' distance
};

// InputError naming `source` for bad settings (stage times, negative horizon).
// `feed`: the head motion, for the ARP's translation (positions) -- optional.
std::vector<std::unique_ptr<DisplayArchitecture>> make_architectures(const DisplayRaster& d, const dp::ArpConfig& c,
                                                                     const LabConfig& lab, const std::string& source,
                                                                     const TrackerFeed* feed = nullptr);

}  // namespace arp::lab
