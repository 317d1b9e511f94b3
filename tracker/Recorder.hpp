// Recording a pose source for a while: everything it delivers until the time
// is up or a stop is asked for (Ctrl-C). Unplugs are survived (the source
// holds its last pose and looks for the device again) and reported through
// the events callback.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "PoseSource.hpp"

namespace arp::tracker {

struct RecordHooks {
  std::function<void(double elapsed_s, size_t samples, bool connected)> progress;  // about every 0.25 s
  std::function<void(const std::string&)> event;                                   // unplug, replug, ...
};

std::vector<PoseSample> record_for(PoseSource& source, double seconds, const std::function<bool()>& stop, const RecordHooks& hooks);

}  // namespace arp::tracker
