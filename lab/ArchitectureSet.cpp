#include "ArchitectureSet.hpp"

#include <cmath>

#include "common/InputError.hpp"

namespace arp::lab {

std::vector<std::unique_ptr<DisplayArchitecture>> make_architectures(const DisplayRaster& d, const dp::ArpConfig& c,
                                                                     const LabConfig& lab, const std::string& source,
                                                                     const TrackerFeed* feed) {
  if (!(lab.horizon_s >= 0) || !std::isfinite(lab.horizon_s) || lab.horizon_s > 1.0)
    throw InputError(source, "prediction horizon", "must be 0 .. 1 s");
  if (!(lab.point_distance_m > 0) || !std::isfinite(lab.point_distance_m)) throw InputError(source, "point distance", "must be positive");
  if (!(lab.arp_threshold_rad >= 0) || lab.arp_threshold_rad > 1.6) throw InputError(source, "theta_t", "must be 0 .. 90 degrees");
  std::vector<std::unique_ptr<DisplayArchitecture>> v;
  ConventionalConfig cc = lab.conventional;
  cc.horizon_s = lab.horizon_s;
  cc.triangles = lab.triangles;
  SlatsConfig sc = lab.slats;
  sc.horizon_s = lab.horizon_s;
  sc.triangles = lab.triangles;
  v.push_back(std::make_unique<ConventionalPipeline>(d, cc, source));
  v.push_back(std::make_unique<SlatsPipeline>(d, sc, source));
  for (JitMode m : {JitMode::PerScanline, JitMode::TwoPerField, JitMode::PerPixel})
    v.push_back(std::make_unique<JustInTimePixels>(d, JitConfig{m, lab.jit_lead_s, lab.triangles, lab.jit_triangles_per_s}, source));
  for (dp::LatchPolicy l : {dp::LatchPolicy::PerFrame, dp::LatchPolicy::PerScanline, dp::LatchPolicy::PerPixel})
    v.push_back(std::make_unique<ArpOrientationPath>(d, c, l, lab.horizon_s, ArpTranslation{feed, lab.arp_threshold_rad, lab.point_distance_m}));
  return v;
}

}  // namespace arp::lab
