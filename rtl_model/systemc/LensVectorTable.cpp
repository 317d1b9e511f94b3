#include "LensVectorTable.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

LensVectorTable::LensVectorTable(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : PipelineStageModule(name, k, cycle, k.lens, {"pixel_requests_in", "view_vectors_out", {"view_x", "view_y", "view_z"}}) {
}

}  // namespace arp::scm
