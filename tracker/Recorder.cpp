#include "Recorder.hpp"

#include <chrono>

namespace arp::tracker {

std::vector<PoseSample> record_for(PoseSource& source, double seconds, const std::function<bool()>& stop, const RecordHooks& hooks) {
  std::vector<PoseSample> poses;
  const auto t0 = std::chrono::steady_clock::now();
  double last_progress = -1;
  for (;;) {
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (el >= seconds || (stop && stop())) break;
    source.poll(poses, 10);
    for (const auto& e : source.take_events())
      if (hooks.event) hooks.event(e);
    if (hooks.progress && el - last_progress >= 0.25) {
      last_progress = el;
      hooks.progress(el, poses.size(), source.connected());
    }
  }
  return poses;
}

}  // namespace arp::tracker
