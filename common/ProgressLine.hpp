// The one progress line: elapsed time and ETA on stderr, redrawn at most
// every 0.25 s and always at completion (then ended with a newline), for
// anything that takes longer than a few seconds. Either give the fraction
// done (update), count steps of a known total (step), or, for a job of
// named steps whose lengths are not known beforehand, the step and the
// fraction of it done (update_step: the ETA is then that step's own).
#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

namespace arp {

class ProgressLine {
 public:
  explicit ProgressLine(std::string prefix, bool enabled = true, int64_t total_steps = 0);
  // Where the line goes and the clock it reads, in seconds from any origin (a test's own).
  ProgressLine(std::string prefix, std::FILE* out, std::function<double()> clock_s);
  // A line left open (an error thrown through the work) is ended, so what is printed next starts a line of its own.
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  void update(double fraction, const std::string& detail);
  // One of `total_steps` done.
  void step(const std::string& detail);
  // Step `step` (1 .. steps) of `steps`, `fraction` of it done. A job's steps can differ in length by orders of
  // magnitude (a plan: a second's harness runs, then a minute's renders), so no fraction of the whole would give
  // an honest ETA; this one is the current step's, from its own start (a step skipped: the number jumps).
  void update_step(int step, int steps, double fraction, const std::string& detail);
  // Ends a line left unfinished (a run stopped before completion); nothing if none is open.
  void finish();

 private:
  double now_s() const;
  // Draws `text` over the line drawn before (padded to its length), ending it when `done`.
  void draw(const std::string& text, bool done);

  std::string prefix_;
  bool enabled_;
  int64_t total_, done_ = 0;
  std::FILE* out_ = stderr;
  std::function<double()> clock_s_;  // empty: the steady clock
  std::chrono::steady_clock::time_point start_;
  double start_s_ = 0, last_ = -1.0;
  int step_ = 0;          // update_step's current step (0: none yet)
  double step_start_ = 0;  // and when it began
  size_t drawn_ = 0;      // characters of the line now shown
  bool open_ = false;     // a line drawn and not yet ended
};

}  // namespace arp
