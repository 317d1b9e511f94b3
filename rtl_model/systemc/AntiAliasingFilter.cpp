#include "AntiAliasingFilter.hpp"

#include <string>

namespace arp::scm {

using namespace sc_core;

AntiAliasingFilter::AntiAliasingFilter(sc_module_name name, cycle::PipelineKernels& k, const int64_t& cycle)
    : PipelineStageModule(name, k, cycle, k.filter, {"composed_taps_in", "pixel_colors_out", {"color", "x", "y"}}) {
}

}  // namespace arp::scm
