#include "ProgressLine.hpp"

#include <cstdio>

namespace arp {

ProgressLine::ProgressLine(std::string prefix, bool enabled, int64_t total_steps)
    : prefix_(std::move(prefix)), enabled_(enabled), total_(total_steps), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(double fraction, const std::string& detail) {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool done = fraction >= 1.0;
  if (!done && s - last_ < 0.25) return;  // a readable rate
  last_ = s;
  const double eta = fraction > 0 ? s * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s: %-12s %5.1f%%  elapsed %6.1f s  ETA %6.1f s ", prefix_.c_str(), detail.c_str(),
               100.0 * fraction, s, eta);
  open_ = !done;
  if (done) std::fprintf(stderr, "\n");
}

void ProgressLine::finish() {
  if (open_) std::fprintf(stderr, "\n");
  open_ = false;
}

void ProgressLine::step(const std::string& detail) {
  ++done_;
  update(total_ > 0 ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0,
         "[" + std::to_string(done_) + "/" + std::to_string(total_) + "] " + detail);
}

}  // namespace arp
