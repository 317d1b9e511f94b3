// HMD scan-out: memory colour codes -> display colour (display_bits per
// channel, rescaled with rounding through per-channel tables), and each
// pixel's photon time: its scan-out cycle in picoseconds plus the panel's delay.
#pragma once
#include <cstdint>
#include <vector>

#include "ArpConfig.hpp"
#include "ClockTime.hpp"
#include "DisplayMemoryBank.hpp"
#include "VideoTiming.hpp"

namespace arp::dp {

class HmdScanOut {
 public:
  HmdScanOut(const MemoryFormat& f, const PipelineConfig& p);
  int display_bits() const { return bits_; }
  // True when memory and display widths match: to_display is the identity.
  bool identity() const { return identity_; }
  // Display pixel, packed R:G:B with display_bits each (red highest).
  uint32_t to_display(uint32_t color) const {
    if (identity_) return color;
    return (lut_[0][(color >> sh_[0]) & mk_[0]] << (2 * bits_)) | (lut_[1][(color >> sh_[1]) & mk_[1]] << bits_) |
           lut_[2][(color >> sh_[2]) & mk_[2]];
  }
  static int64_t photon_time_ps(const VideoTiming& t, const PipelineConfig& p, int64_t frame, int eye, int x, int y) {
    ClockTimeCursor clock(t.config().pixel_clock_hz);
    return photon_time_ps(clock, t, p, frame, eye, x, y);
  }
  // The same through a cursor on the pixel clock: a line's slots, asked for in order, cost no division each.
  static int64_t photon_time_ps(ClockTimeCursor& clock, const VideoTiming& t, const PipelineConfig& p, int64_t frame, int eye,
                                int x, int y) {
    return clock.ps(t.pixel_cycle(frame, eye, x, y)) + p.photon_delay_ps;
  }
  // A whole line, x = 0 .. width - 1: its slots are consecutive clocks (VideoTiming::pixel_cycle is the
  // line's start plus x), so the start is found once and the cursor steps.
  static void photon_times_ps(ClockTimeCursor& clock, const VideoTiming& t, const PipelineConfig& p, int64_t frame,
                              int eye, int y, int width, int64_t* out) {
    const int64_t c0 = t.pixel_cycle(frame, eye, 0, y);
    for (int x = 0; x < width; ++x) out[x] = clock.ps(c0 + x) + p.photon_delay_ps;
  }

 private:
  int bits_;
  bool identity_;
  int sh_[3];
  uint32_t mk_[3];
  std::vector<uint32_t> lut_[3];
};

}  // namespace arp::dp
