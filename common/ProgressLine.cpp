#include "ProgressLine.hpp"

#include <string>

namespace arp {

ProgressLine::ProgressLine(std::string prefix, bool enabled, int64_t total_steps)
    : prefix_(std::move(prefix)), enabled_(enabled), total_(total_steps), start_(std::chrono::steady_clock::now()) {}

ProgressLine::ProgressLine(std::string prefix, std::FILE* out, std::function<double()> clock_s)
    : prefix_(std::move(prefix)), enabled_(true), total_(0), out_(out), clock_s_(std::move(clock_s)) {
  start_s_ = clock_s_();
}

double ProgressLine::now_s() const {
  if (clock_s_) return clock_s_() - start_s_;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressLine::draw(const std::string& text, bool done) {
  // Padded over the longer line before it, so no tail of an earlier detail is left on screen.
  const std::string line = prefix_ + ": " + text;
  std::fprintf(out_, "\r%s%*s", line.c_str(), static_cast<int>(drawn_ > line.size() ? drawn_ - line.size() : 0), "");
  drawn_ = done ? 0 : line.size();
  open_ = !done;
  if (done) std::fprintf(out_, "\n");
  std::fflush(out_);
}

void ProgressLine::update(double fraction, const std::string& detail) {
  if (!enabled_) return;
  const double s = now_s();
  const bool done = fraction >= 1.0;
  if (!done && s - last_ < 0.25) return;  // a readable rate
  last_ = s;
  const double eta = fraction > 0 ? s * (1.0 - fraction) / fraction : 0.0;
  char b[512];
  std::snprintf(b, sizeof b, "%-12s %5.1f%%  elapsed %6.1f s  ETA %6.1f s ", detail.c_str(), 100.0 * fraction, s, eta);
  draw(b, done);
}

void ProgressLine::update_step(int step, int steps, double fraction, const std::string& detail) {
  if (!enabled_) return;
  const double s = now_s();
  const bool next = step != step_;
  if (next) {
    step_ = step;
    step_start_ = s;
  }
  if (!next && fraction < 1.0 && s - last_ < 0.25) return;  // a readable rate; a new step is always shown
  last_ = s;
  const double in_step = s - step_start_;
  char eta[32] = "     ? s";  // nothing done yet: no rate to go by
  if (fraction > 0) std::snprintf(eta, sizeof eta, "%6.1f s", in_step * (1.0 - fraction) / fraction);
  char b[512];
  std::snprintf(b, sizeof b, "[%d/%d] %s %3.0f%%  elapsed %6.1f s  step ETA %s ", step, steps, detail.c_str(),
                100.0 * fraction, s, eta);
  draw(b, false);
}

void ProgressLine::finish() {
  if (open_ && enabled_) std::fprintf(out_, "\n");
  open_ = false;
  drawn_ = 0;
}

void ProgressLine::step(const std::string& detail) {
  ++done_;
  update(total_ > 0 ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0,
         "[" + std::to_string(done_) + "/" + std::to_string(total_) + "] " + detail);
}

}  // namespace arp
