// The ARP in the latency laboratory: head rotation applied at scan-out. The
// orientation register is read for each frame, field, scanline or pixel (the
// pipeline's latch policy) the pipeline's own lead before the pixel's photon
// -- the datapath's latch_cycle and PipelineSchedule, the same arithmetic the
// functional and cycle models use. Translation goes through priority
// rendering and is measured by the host tools, not here (rotation only).
#pragma once
#include "DisplayArchitecture.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::pipelines {

class ArpOrientationPath : public DisplayArchitecture {
 public:
  // The raster must be built from c.timing.
  ArpOrientationPath(const DisplayRaster& d, const dp::ArpConfig& c, dp::LatchPolicy latch, double horizon_s);
  std::string name() const override;
  std::string description() const override;
  void schedule(int64_t, int64_t) override {}
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  double image_interval_s() const override { return static_cast<double>(d_.field_period_ps()) * 1e-12; }

 private:
  const DisplayRaster& d_;
  dp::LatchPolicy latch_;
  int lead_cycles_;
  int64_t horizon_ps_;
};

}  // namespace arp::pipelines
