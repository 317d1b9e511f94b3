#include "SlatsPipeline.hpp"

#include <cmath>
#include <cstdio>

#include "common/InputError.hpp"

namespace arp::lab {

SlatsPipeline::SlatsPipeline(const DisplayRaster& d, const SlatsConfig& c, const std::string& source) : d_(d), c_(c) {
  for (auto [name, v] : {std::pair<const char*, double>{"set-up time", c.setup_s}, {"first-half copy time", c.copy_first_half_s},
                         {"triangle rate", c.triangles_per_s}})
    if (!(v > 0) || !std::isfinite(v)) throw InputError(source, name, "must be a positive number");
  if (!(c.triangles >= 0) || !std::isfinite(c.triangles)) throw InputError(source, "triangles", "must be >= 0");
  if (!(c.horizon_s >= 0) || !std::isfinite(c.horizon_s)) throw InputError(source, "prediction horizon", "must be >= 0");
  const double field = static_cast<double>(d.field_period_ps()) * 1e-12;
  if (c.setup_s + c.copy_first_half_s > field)
    throw InputError(source, "set-up time", "set-up and first-half copy (" + std::to_string((c.setup_s + c.copy_first_half_s) * 1e3) +
                                                " ms) cannot fit one field (" + std::to_string(field * 1e3) + " ms)");
}

bool SlatsPipeline::fits() const {
  const double field = static_cast<double>(d_.field_period_ps()) * 1e-12;
  return c_.setup_s + c_.triangles / c_.triangles_per_s + c_.copy_first_half_s <= field;
}

std::string SlatsPipeline::description() const {
  char b[200];
  std::snprintf(b, sizeof b, "one field of latency; %.0f triangles need %.1f ms of the field's %.1f ms%s", c_.triangles,
                (c_.setup_s + c_.triangles / c_.triangles_per_s + c_.copy_first_half_s) * 1e3,
                static_cast<double>(d_.field_period_ps()) * 1e-9, fits() ? "" : " -- too many: no image");
  return b;
}

void SlatsPipeline::schedule(int64_t first_frame, int64_t last_frame) {
  fields_ = (last_frame - first_frame + 1) * d_.fields_per_frame();
}

PoseUse SlatsPipeline::pose_for(int64_t frame, int, int y) const {
  PoseUse u;
  if (!fits()) {
    u.shown = false;
    return u;
  }
  const int64_t k = frame * d_.fields_per_frame() + d_.timing().field_of_line(y);
  u.compute_ps = d_.field_start_ps(k) - d_.field_period_ps();  // exactly one field before its scan starts
  u.target_ps = u.compute_ps + static_cast<int64_t>(std::llround(c_.horizon_s * 1e12));
  return u;
}

}  // namespace arp::lab
