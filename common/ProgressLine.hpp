// The one progress line: elapsed time and ETA on stderr, redrawn at most
// every 0.25 s and always at completion (then ended with a newline), for
// anything that takes longer than a few seconds. Either give the fraction
// done (update) or count steps of a known total (step).
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace arp {

class ProgressLine {
 public:
  explicit ProgressLine(std::string prefix, bool enabled = true, int64_t total_steps = 0);
  void update(double fraction, const std::string& detail);
  // One of `total_steps` done.
  void step(const std::string& detail);
  // Ends a line left unfinished (a run stopped before completion); nothing if none is open.
  void finish();

 private:
  std::string prefix_;
  bool enabled_;
  int64_t total_, done_ = 0;
  std::chrono::steady_clock::time_point start_;
  double last_ = -1.0;
  bool open_ = false;  // a line drawn and not yet ended
};

}  // namespace arp
