#include "OrientationMatrixUnit.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

OrientationMatrixUnit::OrientationMatrixUnit(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : PipelineStageModule(name, k, cycle, k.rotate, {"view_vectors_in", "world_vectors_out", {"world_x", "world_y", "world_z"}}) {
}

void OrientationMatrixUnit::trace_more(sc_trace_file* tf, const std::string& n) const {
  sc_trace(tf, k_.latch.sample, n + ".matrix_sample");
  for (int i = 0; i < 9; ++i) sc_trace(tf, k_.latch.matrix.m[i], n + ".matrix_" + std::to_string(i / 3) + std::to_string(i % 3));
}

}  // namespace arp::scm
