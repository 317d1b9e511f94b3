// Slats (Olano et al. 1995, section 5.3): exactly one field of latency. All
// the work for a field -- transform and render of that field's lines only,
// both eyes together -- is done during the field before it, starting at its
// first line; the first half of the copy must finish before the vertical
// retrace. A scene too large for the deadline cannot be drawn at all ("Slats
// fails to generate a correct image"): every field is then missed.
#pragma once
#include "DisplayArchitecture.hpp"

namespace arp::lab {

struct SlatsConfig {
  double setup_s = 0.001;         // fixed transform and render work per field
  double copy_first_half_s = 0.0039;  // must also fit before the retrace
  double triangles = 0;
  double triangles_per_s = 12000; // one GP (Olano et al.: about 100 triangles per field)
  double horizon_s = 0.0;
};

class SlatsPipeline : public DisplayArchitecture {
 public:
  // InputError naming `source` when the fixed work cannot fit one field.
  SlatsPipeline(const DisplayRaster& d, const SlatsConfig& c, const std::string& source);
  std::string name() const override { return "slats"; }
  std::string description() const override;
  void schedule(int64_t first_frame, int64_t last_frame) override;
  PoseUse pose_for(int64_t frame, int x, int y) const override;
  int64_t missed_images() const override { return fits() ? 0 : fields_; }
  double image_interval_s() const override { return static_cast<double>(d_.field_period_ps()) * 1e-12; }
  bool fits() const;  // the scene's work meets the deadline

 private:
  const DisplayRaster& d_;
  SlatsConfig c_;
  int64_t fields_ = 0;
};

}  // namespace arp::lab
