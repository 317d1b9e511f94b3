#include "JustInTimePixels.hpp"

#include <cmath>
#include <cstdio>

#include "common/InputError.hpp"

namespace arp::lab {

const EnumNames<JitMode>& jit_mode_names() {
  static const EnumNames<JitMode> n{{JitMode::PerScanline, "scanline"}, {JitMode::TwoPerField, "two-per-field"}, {JitMode::PerPixel, "pixel"}};
  return n;
}

JustInTimePixels::JustInTimePixels(const DisplayRaster& d, const JitConfig& c, const std::string& source) : d_(d), c_(c) {
  if (c.lead_s != -1 && (!(c.lead_s >= 0) || c.lead_s > 1.0)) throw InputError(source, "JITP lead", "must be 0 .. 1 s (-1: one line)");
  if (!(c.triangles >= 0) || !std::isfinite(c.triangles)) throw InputError(source, "triangles", "must be >= 0");
  if (!(c.triangles_per_s > 0) || !std::isfinite(c.triangles_per_s)) throw InputError(source, "JITP triangle rate", "must be positive");
  lead_ps_ = c.lead_s == -1 ? d.line_period_ps() : static_cast<int64_t>(std::llround(c.lead_s * 1e12));
}

bool JustInTimePixels::fits() const {
  const double work = c_.triangles / c_.triangles_per_s;
  switch (c_.mode) {
    case JitMode::PerScanline: return work <= static_cast<double>(d_.line_period_ps()) * 1e-12;
    case JitMode::TwoPerField: return 2 * work <= static_cast<double>(d_.field_period_ps()) * 1e-12;
    case JitMode::PerPixel: return work <= 1.0 / static_cast<double>(d_.timing().config().pixel_clock_hz);
  }
  return false;
}

std::string JustInTimePixels::name() const { return std::string("jitp-") + to_string(c_.mode); }

std::string JustInTimePixels::description() const {
  char b[160];
  switch (c_.mode) {
    case JitMode::PerScanline: std::snprintf(b, sizeof b, "a transform per scanline, computed %.1f us ahead", static_cast<double>(lead_ps_) * 1e-6); break;
    case JitMode::TwoPerField: std::snprintf(b, sizeof b, "two transforms per field (first and last pixel), interpolated, computed a field ahead"); break;
    case JitMode::PerPixel: std::snprintf(b, sizeof b, "a transform per pixel, computed %.1f us ahead", static_cast<double>(lead_ps_) * 1e-6); break;
  }
  std::string out = b;
  if (c_.triangles > 0) out += (fits() ? "; " : "; too slow for ") + std::to_string(static_cast<long long>(c_.triangles)) + " triangles per transform";
  return out;
}

PoseUse JustInTimePixels::pose_for(int64_t frame, int x, int y) const {
  PoseUse u;
  if (!fits()) {
    u.shown = false;
    return u;
  }
  switch (c_.mode) {
    case JitMode::PerScanline:
      u.target_ps = d_.photon_ps(frame, 0, y);
      u.compute_ps = u.target_ps - lead_ps_;
      break;
    case JitMode::PerPixel:
      u.target_ps = d_.photon_ps(frame, x, y);
      u.compute_ps = u.target_ps - lead_ps_;
      break;
    case JitMode::TwoPerField: {
      const int field = d_.timing().field_of_line(y);
      const int fpf = d_.fields_per_frame();
      // The field's first and last active lines.
      const int first_line = field, last_line = field + ((d_.height() - 1 - field) / fpf) * fpf;
      u.target_ps = d_.photon_ps(frame, 0, first_line);
      u.target2_ps = d_.photon_ps(frame, d_.width() - 1, last_line);
      u.compute_ps = u.compute2_ps = d_.field_start_ps(frame, field) - d_.field_period_ps();
      const int64_t t = d_.photon_ps(frame, x, y);
      u.blend = static_cast<double>(t - u.target_ps) / static_cast<double>(std::max<int64_t>(1, u.target2_ps - u.target_ps));
      break;
    }
  }
  return u;
}

}  // namespace arp::lab
