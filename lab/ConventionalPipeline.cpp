#include "ConventionalPipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/InputError.hpp"

namespace arp::lab {

namespace {
int64_t ps(double s) { return static_cast<int64_t>(std::llround(s * 1e12)); }
}  // namespace

ConventionalPipeline::ConventionalPipeline(const DisplayRaster& d, const ConventionalConfig& c, const std::string& source)
    : d_(d), c_(c) {
  for (auto [name, v] : {std::pair<const char*, double>{"transform time", c.transform_s}, {"render time", c.render_s},
                         {"copy time", c.copy_s}, {"triangle rate", c.triangles_per_s}})
    if (!(v > 0) || !std::isfinite(v)) throw InputError(source, name, "must be a positive number");
  if (!(c.triangles >= 0) || !std::isfinite(c.triangles)) throw InputError(source, "triangles", "must be >= 0");
  if (!(c.horizon_s >= 0) || !std::isfinite(c.horizon_s)) throw InputError(source, "prediction horizon", "must be >= 0");
  if (render_stage_s() > 10.0) throw InputError(source, "render time", "more than 10 s per frame");
}

std::string ConventionalPipeline::description() const {
  char b[200];
  std::snprintf(b, sizeof b, "PPHIGS-like: transform %.1f ms, render %.1f ms, copy %.1f ms per stereo pair%s", c_.transform_s * 1e3,
                render_stage_s() * 1e3, c_.copy_s * 1e3, c_.field_sync ? ", stages synchronised to fields" : "");
  return b;
}

int64_t ConventionalPipeline::sync(int64_t t) const {
  if (!c_.field_sync) return t;
  return d_.field_start_ps(d_.first_field_swapped_after(t)) - d_.vblank_ps();
}

void ConventionalPipeline::schedule(int64_t first_frame, int64_t last_frame) {
  frames_.clear();
  const int fpf = d_.fields_per_frame();
  first_field_ = std::max<int64_t>(0, first_frame * fpf);
  const int64_t last_field = (last_frame + 1) * fpf;
  shown_by_field_.assign(static_cast<size_t>(last_field - first_field_ + 1), -1);
  // Start well before the first refresh so the pipeline is full by then.
  const int64_t lead = ps(c_.transform_s + render_stage_s() + c_.copy_s) + 4 * d_.field_period_ps();
  int64_t t0 = d_.field_start_ps(first_field_) - lead;
  FrameTimes prev{t0, t0, t0, t0, t0, t0, -1};
  bool first = true;
  for (;;) {
    FrameTimes f{};
    // One buffer between stages: a stage starts when it is free and the next
    // stage has taken its previous output; the copy waits for the back buffer
    // (the one the display stopped showing when the previous frame went up).
    f.transform_start = sync(first ? t0 : std::max(prev.transform_end, prev.render_start));
    f.transform_end = f.transform_start + ps(c_.transform_s);
    f.render_start = sync(first ? f.transform_end : std::max({f.transform_end, prev.render_end, prev.copy_start}));
    f.render_end = f.render_start + ps(render_stage_s());
    const int64_t back_free = first ? f.render_end : d_.field_start_ps(prev.shown_field) - d_.vblank_ps();
    f.copy_start = sync(first ? f.render_end : std::max({f.render_end, prev.copy_end, back_free}));
    f.copy_end = f.copy_start + ps(c_.copy_s);
    f.shown_field = d_.first_field_swapped_after(f.copy_end);
    first = false;
    frames_.push_back(f);
    prev = f;
    if (f.shown_field > last_field) break;
  }
  // Which frame each field shows: the latest shown at or before it.
  int64_t cur = -1;
  size_t next = 0;
  for (int64_t k = first_field_; k <= last_field; ++k) {
    while (next < frames_.size() && frames_[next].shown_field <= k) cur = static_cast<int64_t>(next++);
    shown_by_field_[static_cast<size_t>(k - first_field_)] = cur;
  }
  // Mean interval between new images over the window.
  int64_t n = 0, lo = -1, hi = -1;
  for (const auto& f : frames_)
    if (f.shown_field >= first_field_ && f.shown_field <= last_field) {
      ++n;
      if (lo < 0) lo = f.shown_field;
      hi = f.shown_field;
    }
  interval_s_ = n > 1 ? static_cast<double>(hi - lo) * static_cast<double>(d_.field_period_ps()) * 1e-12 / static_cast<double>(n - 1)
                      : static_cast<double>(last_field - first_field_) * static_cast<double>(d_.field_period_ps()) * 1e-12;
  // Fields that repeated an image: the pipeline did not keep up with the display.
  dropped_ = (last_field - first_field_ + 1) - n;
}

PoseUse ConventionalPipeline::pose_for(int64_t frame, int, int y) const {
  const int64_t k = frame * d_.fields_per_frame() + d_.timing().field_of_line(y);
  PoseUse u;
  const int64_t i = k >= first_field_ && k - first_field_ < static_cast<int64_t>(shown_by_field_.size())
                        ? shown_by_field_[static_cast<size_t>(k - first_field_)]
                        : -1;
  if (i < 0) {
    u.shown = false;
    return u;
  }
  u.compute_ps = frames_[static_cast<size_t>(i)].transform_start;
  u.target_ps = u.compute_ps + ps(c_.horizon_s);
  return u;
}

}  // namespace arp::lab
