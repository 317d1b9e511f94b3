// Orientation matrix unit: loads the orientation register at latch points
// and rotates each view vector into the cube frame (stage::OrientationStage).
#pragma once
#include "StageModule.hpp"
#include "rtl_model/stages/OrientationStage.hpp"

namespace arp::scm {

class OrientationMatrixUnit : public StageModule<stage::OrientationStage> {
 public:
  static constexpr const char* kInput = "view_vectors", *kOutput = "world_vectors";
  static constexpr const char* kInstance = "orientation_matrix_unit";
  sc_core::sc_port<FifoReadIf<stage::LensToken>>& view_vectors_in = input;
  sc_core::sc_port<FifoWriteIf<stage::RotatedToken>>& world_vectors_out = output;

  OrientationMatrixUnit(sc_core::sc_module_name name, const stage::StageContext& ctx);

 private:
  void trace_more(sc_core::sc_trace_file* tf, const std::string& n) const override;
};

}  // namespace arp::scm
