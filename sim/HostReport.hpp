// The host's part of a run's report: per display memory, its update rate and
// rendering load; against rendering everything every frame; the regions.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "RunSpec.hpp"
#include "host/priority/HostSimulation.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "host/regions/Segmentation.hpp"

namespace arp::sim {

nlohmann::json host_report(const host::HostSimulation& h, const RunSpec& spec, double display_hz, int64_t baseline_triangles,
                           double host_wall_s, const host::RegionScheduler* regions, const host::RegionGrid* grid,
                           const host::Segmented& segmented, size_t objects_after_segmentation, double px_rad);

// The memories of host_report() as CSV, one row per memory.
std::string host_csv(const nlohmann::json& memories);

}  // namespace arp::sim
