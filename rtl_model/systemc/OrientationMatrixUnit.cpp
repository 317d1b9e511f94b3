#include "OrientationMatrixUnit.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

OrientationMatrixUnit::OrientationMatrixUnit(sc_module_name name, const stage::StageContext& ctx)
    : StageModule(name, ctx, kInput, kOutput, {"world_x", "world_y", "world_z"}) {}

// The matrix register and the tracker sample it holds.
void OrientationMatrixUnit::trace_more(sc_trace_file* tf, const std::string& n) const {
  sc_trace(tf, stage_.sample, n + ".matrix_sample");
  for (int i = 0; i < 9; ++i) sc_trace(tf, stage_.matrix.m[i], n + ".matrix_" + std::to_string(i / 3) + std::to_string(i % 3));
}

}  // namespace arp::scm
