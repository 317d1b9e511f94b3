// The display every architecture of the latency laboratory drives: the
// pipeline's own video timing (so photon times are the scan-out's, including
// interlaced fields) and a pinhole view of the configured field of view.
// Registration error is measured as an angle and converted with the display's
// pixels per degree across the field of view -- Olano et al.'s conversion
// (600 pixels over 60 degrees: 10 px per degree).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::lab {

// Olano et al.'s display: NTSC-like interlaced video, 600 active pixels
// across (their 60-degree field of view), 480 active of 525 lines, two fields
// per frame at 59.94 fields/s, 63.6 us lines.
dp::VideoTimingConfig ntsc_like_timing();

class DisplayRaster {
 public:
  DisplayRaster(const dp::VideoTimingConfig& timing, double fov_deg);

  const dp::VideoTiming& timing() const { return t_; }
  int width() const { return t_.config().h_active; }
  int height() const { return t_.config().v_active; }
  int fields_per_frame() const { return t_.config().fields_per_frame; }
  double fov_deg() const { return fov_deg_; }
  double pixels_per_degree() const { return width() / fov_deg_; }

  // Photon time of active pixel (x, y) of eye 0 in refresh `frame` (lock-step eyes share it).
  int64_t photon_ps(int64_t frame, int x, int y) const;
  // Start of the active part of field `field` of `frame` (its first pixel's photon).
  int64_t field_start_ps(int64_t frame, int field) const;
  // Field k counted from frame 0 field 0 (k = frame * fields + field).
  int64_t field_start_ps(int64_t k) const { return field_start_ps(k / fields_per_frame(), static_cast<int>(k % fields_per_frame())); }
  // The vertical blank before field k begins this long before its first pixel.
  int64_t vblank_ps() const { return vblank_ps_; }
  int64_t field_period_ps() const { return field_start_ps(1) - field_start_ps(0); }
  int64_t line_period_ps() const;
  // The first field whose vertical blank starts at or after t (a buffer swapped by t is shown from it).
  int64_t first_field_swapped_after(int64_t t_ps) const;
  // The last refresh whose first pixel is at or before t (-1 before frame 0).
  int64_t frame_at(int64_t t_ps) const;

  // Head-frame direction through the centre of pixel (x, y) (x right, y down the screen; looking down -z).
  glm::dvec3 ray(double x, double y) const;

 private:
  dp::VideoTiming t_;
  double fov_deg_;
  double focal_px_;
  int64_t vblank_ps_;
};

}  // namespace arp::lab
