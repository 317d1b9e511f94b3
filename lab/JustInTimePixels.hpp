// Just-in-time pixels (Olano et al. 1995, section 4): each pixel computed for
// its own display time, by beam racing. Per scanline: one transform per line,
// computed `lead` before the line is scanned, for the line's display time.
// Two per field: transforms for the field's first and last pixel, computed a
// field ahead, with orientations interpolated between them for the pixels in
// between. Per pixel: a transform for every pixel, `lead` before it. Each
// transform predicts the latest tracker report to its display time (with the
// laboratory's predictor; without one it uses the report as it is).
// Work: every transform processes the whole scene (triangles / rate), and it
// must fit the time it races -- a line, half a field for each of the two
// field transforms, or a pixel; a scene that does not fit cannot be shown.
#pragma once
#include "DisplayArchitecture.hpp"
#include "common/Parameter.hpp"

namespace arp::lab {

enum class JitMode { PerScanline, TwoPerField, PerPixel };
const EnumNames<JitMode>& jit_mode_names();  // scanline, two-per-field, pixel
inline bool parse_jit_mode(const std::string& s, JitMode& out) { return enum_parse(jit_mode_names(), s, out); }
inline std::string to_string(JitMode m) { return enum_name(jit_mode_names(), m); }

struct JitConfig {
  JitMode mode = JitMode::PerScanline;
  double lead_s = -1;  // compute this long before display (-1: one line period)
  double triangles = 0;
  double triangles_per_s = 2e6;
};

class JustInTimePixels : public DisplayArchitecture {
 public:
  JustInTimePixels(const DisplayRaster& d, const JitConfig& c, const std::string& source);
  std::string name() const override;
  std::string description() const override;
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  double image_interval_s() const override { return static_cast<double>(d_.field_period_ps()) * 1e-12; }
  int64_t missed_images() const override { return fits() ? 0 : fields_; }
  bool fits() const;  // the scene's work per transform fits the time it races
  void schedule(int64_t first, int64_t last) override { fields_ = (last - first + 1) * d_.fields_per_frame(); }

 private:
  const DisplayRaster& d_;
  JitConfig c_;
  int64_t lead_ps_;
  int64_t fields_ = 0;
};

}  // namespace arp::lab
