#include "VideoTiming.hpp"

#include <cinttypes>
#include <cstdio>

#include "ClockTime.hpp"

namespace arp::dp {

namespace {
__extension__ typedef __int128 i128;
}  // namespace

VideoTiming::VideoTiming(const VideoTimingConfig& c)
    : c_(c), frame_cycles_(int64_t{c.h_total()} * c.v_total()) {}

double VideoTiming::refresh_hz() const {
  return static_cast<double>(c_.pixel_clock_hz) / static_cast<double>(frame_cycles_);
}

int64_t VideoTiming::cycles_to_ps(int64_t cycles) const { return clock_cycle_to_ps(cycles, c_.pixel_clock_hz); }

int64_t VideoTiming::ps_to_cycle_floor(int64_t ps) const { return clock_cycle_at_or_before(ps, c_.pixel_clock_hz); }

int64_t VideoTiming::last_frame_in_range() const {
  return last_clock_cycle_in_range(c_.pixel_clock_hz) / frame_cycles_ - 2;  // less the frame after the last one
}

std::string VideoTiming::frames_out_of_range(int64_t first, int64_t count) const {
  if (first < 0) return "frame " + std::to_string(first) + " is before frame 0";
  const int64_t last = last_frame_in_range();
  const i128 asked = static_cast<i128>(first) + count - 1;
  if (count < 1 || asked <= last) return "";
  char b[240];
  std::snprintf(b, sizeof b,
                "frame %s is past the last frame whose times fit in arpsim's 64-bit picoseconds: frame %" PRId64
                " (%.1f days at this display's %.4g Hz)",
                asked > INT64_MAX ? "9223372036854775808 or more" : std::to_string(static_cast<int64_t>(asked)).c_str(), last,
                static_cast<double>(last) / refresh_hz() / 86400.0, refresh_hz());
  return b;
}

}  // namespace arp::dp
