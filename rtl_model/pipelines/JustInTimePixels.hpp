// Just-in-time pixels (Olano et al. 1995, section 4): each pixel computed for
// its own display time, by beam racing. Per scanline: one transform per line,
// computed `lead` before the line is scanned, for the line's display time.
// Two per field: transforms for the field's first and last pixel, computed a
// field ahead, with orientations interpolated between them for the pixels in
// between. Per pixel: a transform for every pixel, `lead` before it. Each
// transform predicts the latest tracker report to its display time (with the
// laboratory's predictor; without one it uses the report as it is).
#pragma once
#include "DisplayArchitecture.hpp"

namespace arp::pipelines {

enum class JitMode { PerScanline, TwoPerField, PerPixel };
bool parse_jit_mode(const std::string& s, JitMode& out);
const char* to_string(JitMode m);

struct JitConfig {
  JitMode mode = JitMode::PerScanline;
  double lead_s = -1;  // compute this long before display (-1: one line period)
};

class JustInTimePixels : public DisplayArchitecture {
 public:
  JustInTimePixels(const DisplayRaster& d, const JitConfig& c, const std::string& source);
  std::string name() const override;
  std::string description() const override;
  void schedule(int64_t, int64_t) override {}
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  double image_interval_s() const override { return static_cast<double>(d_.field_period_ps()) * 1e-12; }

 private:
  const DisplayRaster& d_;
  JitConfig c_;
  int64_t lead_ps_;
};

}  // namespace arp::pipelines
