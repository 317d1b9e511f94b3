// The ARP in the latency laboratory: head rotation applied at scan-out. The
// orientation register is read for each frame, field, scanline or pixel (the
// pipeline's latch policy) the pipeline's own lead before the pixel's photon
// -- the datapath's LatchRule and PipelineSchedule, the same arithmetic the
// functional and cycle models use.
//
// Translation goes through priority rendering: the display memory holding a
// tracked point is re-rendered on need -- when the head has moved more than
// D·sqrt(2(1 − cos θt)) from where it was last rendered (D the point's
// distance, θt the threshold angle; Chow 2005, issue 4's validity rule) --
// decided at a vertical blank from the latest tracker report, rendered
// during the next frame and shown from the one after. One memory for the
// tracked points (they are all at distance D); the host's full scheduler is
// in host/priority.
#pragma once
#include <vector>

#include "DisplayArchitecture.hpp"
#include "TrackerFeed.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::lab {

struct ArpTranslation {
  const TrackerFeed* feed = nullptr;  // the head's positions (none: rotation only)
  double threshold_rad = 0;           // θt; 0: one display-memory texel, the host's default
  double point_distance_m = 2.0;
};

class ArpOrientationPath : public DisplayArchitecture {
 public:
  // The raster must be built from c.timing.
  ArpOrientationPath(const DisplayRaster& d, const dp::ArpConfig& c, dp::LatchPolicy latch, double horizon_s,
                     const ArpTranslation& translation = {});
  std::string name() const override;
  std::string description() const override;
  void schedule(int64_t first_frame, int64_t last_frame) override;
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  double image_interval_s() const override { return static_cast<double>(d_.field_period_ps()) * 1e-12; }
  // Re-renders of the memory for translation over the scheduled frames.
  int64_t translation_renders() const { return renders_; }

 private:
  const DisplayRaster& d_;
  dp::LatchPolicy latch_;
  dp::LatchRule rule_;  // the datapath's latch rule under this path's policy
  int64_t horizon_ps_;
  ArpTranslation tr_;
  int64_t first_ = 0, renders_ = 0;
  std::vector<int64_t> position_ps_;  // per scheduled frame: the position its memory was rendered from
};

}  // namespace arp::lab
