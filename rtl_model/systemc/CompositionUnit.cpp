#include "CompositionUnit.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

CompositionUnit::CompositionUnit(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : PipelineStageModule(name, k, cycle, k.compose, {"texel_words_in", "composed_taps_out", {"color_tap0", "color_tap1", "weight_x"}}) {
}

}  // namespace arp::scm
