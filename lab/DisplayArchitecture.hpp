// One display architecture of the latency laboratory: for every displayed
// pixel, which head orientation it was computed with -- when the system read
// the tracker (the render start, as the oscilloscope's D/A signal shows it)
// and which time it predicted that report to. Two transforms blended per
// pixel cover just-in-time pixels' "two transformations per field".
#pragma once
#include <cstdint>
#include <string>

#include "DisplayRaster.hpp"

namespace arp::lab {

struct PoseUse {
  int64_t compute_ps = 0;   // the system reads the latest tracker report
  int64_t target_ps = 0;    // and predicts it to this time (ignored without prediction)
  // A second transform, blended in with weight `blend` (0: unused).
  int64_t compute2_ps = 0, target2_ps = 0;
  double blend = 0.0;
  bool shown = true;        // false before the architecture's first image
  // The head position the image was drawn from: the true position at this
  // time (-1: the position in the same tracker report as the orientation).
  // The ARP draws translation through priority rendering, so its position
  // is the one its display memory was last rendered from.
  int64_t position_ps = -1;
};

class DisplayArchitecture {
 public:
  virtual ~DisplayArchitecture() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  // Called once before any pose_for, for refreshes [first, last].
  virtual void schedule(int64_t first_frame, int64_t last_frame) = 0;
  virtual PoseUse pose_for(int64_t frame, int x, int y) const = 0;
  // Images that could not be made in time (Slats' deadline, conventional
  // frames dropped because the pipeline fell behind); 0 when it cannot fail.
  virtual int64_t missed_images() const { return 0; }
  // Mean interval between new images, seconds (display refreshes for the ARP and JITP).
  virtual double image_interval_s() const = 0;
};

}  // namespace arp::lab
