#include "HostReport.hpp"

#include "common/Units.hpp"

namespace arp::sim {

nlohmann::json host_report(const host::HostSimulation& h, const RunSpec& spec, double display_hz, int64_t baseline_triangles,
                           double host_wall_s, const host::RegionScheduler* regions, const host::RegionGrid* grid,
                           const host::Segmented& segmented, size_t objects_after_segmentation, double px_rad) {
  const HostSpec& hs = spec.host;
  const double secs = static_cast<double>(spec.frames) / display_hz;
  nlohmann::json mems = nlohmann::json::array();
  int64_t tris = 0;
  for (size_t m = 0; m < h.load().size(); ++m) {
    const auto& L = h.load()[m];
    tris += L.triangles;
    const double n = L.updates > 0 ? static_cast<double>(L.updates) : 1.0;
    mems.push_back({{"memory", m},
                    {"objects_now", h.objects_for(static_cast<int>(m)).size()},
                    {"updates", L.updates},
                    {"skipped_overload", L.skipped},
                    {"update_rate_hz", static_cast<double>(L.updates) / secs},
                    {"objects_per_update", static_cast<double>(L.objects) / n},
                    {"triangles_per_update", static_cast<double>(L.triangles) / n},
                    {"triangles_per_s", static_cast<double>(L.triangles) / secs},
                    {"texels_per_s", static_cast<double>(L.texels) / secs},
                    {"engine_busy_s", L.busy_s}});
  }
  nlohmann::json r{
      {"threshold_deg", rad_to_deg(h.scheduler().threshold_rad())},
      {"mode", regions ? "regions" : (hs.baseline ? "baseline" : "objects")},
      {"baseline", hs.baseline},
      {"engine",
       {{"triangles_per_s", spec.config.host.triangles_per_s}, {"texels_per_s", spec.config.host.texels_per_s},
        {"object_setup_s", spec.config.host.object_setup_s}}},
      {"memories", mems},
      {"object_moves", h.scheduler().moves()},
      {"object_frames_held_faster_for_tiles", h.held_back()},
      {"object_frames_kept_faster_for_tile_pool", h.kept_for_pool()},
      {"object_frames_held_slower_by_assignment", h.scheduler().held_slower()},
      {"object_frames_held_faster_by_assignment", h.scheduler().held_faster()},
      {"triangles_per_s", static_cast<double>(tris) / secs},
      {"full_render_every_frame_triangles_per_s", static_cast<double>(baseline_triangles) / secs},
      {"load_reduction", tris > 0 ? static_cast<double>(baseline_triangles) / static_cast<double>(tris) : 0.0},
      {"host_wall_ms_per_frame", 1e3 * host_wall_s / static_cast<double>(spec.frames)}};
  if (regions)
    r["regions"] = {{"size_m", spec.config.memory.region_size_m},
                    {"margin_m", spec.config.memory.region_margin_m},
                    {"shape", hs.region_cubes ? "cubes" : "columns"},
                    {"regions", grid->count()},
                    {"segmentation", hs.segmentation},
                    {"objects_cut", segmented.objects_cut},
                    {"segments", segmented.segments},
                    {"objects_after_segmentation", objects_after_segmentation},
                    {"reassignments", regions->reassignments()},
                    {"warping", hs.warp},
                    {"max_warp_displacement_px", h.max_warp_rad() / px_rad}};
  return r;
}

std::string host_csv(const nlohmann::json& memories) {
  std::string hc = "memory,updates,skipped_overload,update_rate_hz,objects_per_update,triangles_per_update,triangles_per_s,texels_per_s\n";
  for (const auto& m : memories)
    hc += std::to_string(m["memory"].get<int>()) + "," + std::to_string(m["updates"].get<int64_t>()) + "," +
          std::to_string(m["skipped_overload"].get<int64_t>()) + "," + std::to_string(m["update_rate_hz"].get<double>()) + "," +
          std::to_string(m["objects_per_update"].get<double>()) + "," + std::to_string(m["triangles_per_update"].get<double>()) +
          "," + std::to_string(m["triangles_per_s"].get<double>()) + "," + std::to_string(m["texels_per_s"].get<double>()) + "\n";
  return hc;
}

}  // namespace arp::sim
