#include "CubeFaceAddressGenerator.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

CubeFaceAddressGenerator::CubeFaceAddressGenerator(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : PipelineStageModule(name, k, cycle, k.address, {"world_vectors_in", "cube_addresses_out", {"face", "texel_x", "texel_y"}}) {
}

}  // namespace arp::scm
