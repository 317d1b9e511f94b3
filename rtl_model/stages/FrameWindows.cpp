#include "FrameWindows.hpp"

#include <algorithm>

namespace arp::stage {

FrameWindows::FrameWindows(std::vector<Window> windows) : all_(false) {
  std::sort(windows.begin(), windows.end());
  for (const Window& w : windows) {
    if (w.second <= w.first) continue;
    if (!w_.empty() && w.first <= w_.back().second) w_.back().second = std::max(w_.back().second, w.second);
    else w_.push_back(w);
  }
}

bool FrameWindows::contains(int64_t frame) const {
  if (all_) return true;
  // The last window starting at or before the frame.
  auto it = std::upper_bound(w_.begin(), w_.end(), frame, [](int64_t f, const Window& w) { return f < w.first; });
  return it != w_.begin() && frame < std::prev(it)->second;
}

}  // namespace arp::stage
