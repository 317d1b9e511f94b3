// Video timing: where every active pixel sits in the pixel-clock sequence.
// Cycle 0 of a frame is its first active pixel; blanking follows the active
// lines (front porch, sync, back porch). Time is integer picoseconds.
#pragma once
#include <cstdint>
#include <string>

#include "ArpConfig.hpp"

namespace arp::dp {

class VideoTiming {
 public:
  explicit VideoTiming(const VideoTimingConfig& c);

  const VideoTimingConfig& config() const { return c_; }
  int64_t frame_cycles() const { return frame_cycles_; }
  int64_t field_cycles() const { return frame_cycles_ / c_.fields_per_frame; }
  double refresh_hz() const;

  int field_of_line(int y) const { return y % c_.fields_per_frame; }
  int64_t frame_start_cycle(int64_t frame) const { return frame * frame_cycles_; }
  int64_t field_start_cycle(int64_t frame, int field) const {
    return frame_start_cycle(frame) + field * field_cycles();
  }
  // Cycle at which active line y begins (x = 0 of eye 0).
  int64_t line_start_cycle(int64_t frame, int y) const {
    const int f = field_of_line(y);
    return field_start_cycle(frame, f) + int64_t{y / c_.fields_per_frame} * c_.h_total();
  }
  // Cycle at which active pixel (x, y) of `eye` is scanned out. Lock-step eyes
  // share the cycle; a side-by-side panel scans the left eye, then the right.
  int64_t pixel_cycle(int64_t frame, int eye, int x, int y) const {
    const int64_t eye_offset = c_.eye_scan == EyeScan::SideBySide ? int64_t{eye} * c_.h_active : 0;
    return line_start_cycle(frame, y) + eye_offset + x;
  }

  // Exact conversions: ps = floor(cycles * 1e12 / f_pixel); std::overflow_error
  // for a time outside the 64-bit picosecond range (never a wrapped time).
  int64_t cycles_to_ps(int64_t cycles) const;
  // A frame's start in seconds, as the host is told it before the frame (and a plan replays it): its picosecond
  // start, a whole picosecond, as a double.
  double frame_start_s(int64_t frame) const { return static_cast<double>(cycles_to_ps(frame_start_cycle(frame))) * 1e-12; }
  // The last cycle that starts at or before ps.
  int64_t ps_to_cycle_floor(int64_t ps) const;

  // Time is int64 picoseconds: about 106 days from time zero. The last frame
  // whose every time -- its pixels, the frame after it (the pipeline's
  // latency and leads) -- fits; it falls with the pixel clock.
  int64_t last_frame_in_range() const;
  // Empty if frames [first, first + count) fit; else why not, with the limit
  // stated, for an InputError naming the option that asked for them.
  std::string frames_out_of_range(int64_t first, int64_t count) const;

 private:
  VideoTimingConfig c_;
  int64_t frame_cycles_;
};

}  // namespace arp::dp
