// Which frames of a run a timed level simulates clock by clock: windows of
// absolute frame numbers, [first, end) each. Default: every frame (a run
// simulated at one level from its first frame to its last). A run with
// detailed windows (--detail) gives its timed level these windows; the other
// frames are computed by the functional model while the timed level idles.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

namespace arp::stage {

class FrameWindows {
 public:
  using Window = std::pair<int64_t, int64_t>;  // [first, end)
  FrameWindows() = default;
  // Only these: sorted, and windows that overlap or touch merged; empty ones dropped.
  explicit FrameWindows(std::vector<Window> windows);

  bool every_frame() const { return all_; }
  bool contains(int64_t frame) const;
  const std::vector<Window>& windows() const { return w_; }

 private:
  std::vector<Window> w_;
  bool all_ = true;
};

}  // namespace arp::stage
