#include "StillFrame.hpp"

#include <algorithm>
#include <chrono>

#include "ConfigFile.hpp"
#include "HardwareCost.hpp"
#include "common/InputError.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

namespace arp::sim {

StillFrame render_still(const StillSpec& spec) {
  check_model_fits_memory(spec.config, spec.config_source, !spec.memories.scene.empty());
  const FunctionalModel model(spec.config);
  if (const std::string why = model.timing().frames_out_of_range(spec.frame, 1); !why.empty())
    throw InputError("--frame", "", why);
  dp::DisplayMemorySet mem(spec.config.memory, spec.config.timing.eyes);
  StillFrame s;
  MemoryContents contents = spec.memories;
  contents.expect_plan(spec.config, spec.config_source);
  contents.fill(mem, spec.orientation, s.source, spec.threads);
  RenderOptions ro;
  ro.threads = spec.threads;
  ro.photon_times = true;
  const auto t0 = std::chrono::steady_clock::now();
  model.render(mem, dp::OrientationStream::constant(spec.orientation), spec.frame, s.frame, ro);
  s.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const auto [pmin, pmax] = std::minmax_element(s.frame.photon_ps.begin(), s.frame.photon_ps.end());
  s.first_photon_ps = *pmin;
  s.last_photon_ps = *pmax;
  s.memory_bytes = mem.bytes_allocated();
  s.lost_on_absent_faces = mem.writes_lost();
  s.lost_off_tiles = mem.writes_lost_off_tiles();
  s.lost_pool_full = mem.writes_lost_pool_full();
  s.refresh_hz = model.timing().refresh_hz();
  return s;
}

nlohmann::json still_report(const StillSpec& spec, const StillFrame& f, const std::string& image) {
  const dp::Quat& q = spec.orientation;
  return {{"image", image},
          {"source", f.source},
          {"quaternion_wxyz", {q.w, q.x, q.y, q.z}},
          {"frame", spec.frame},
          {"refresh_hz", f.refresh_hz},
          {"first_photon_ps", f.first_photon_ps},
          {"last_photon_ps", f.last_photon_ps},
          {"display_memory_bytes", f.memory_bytes},
          {"texels_lost_on_absent_faces", f.lost_on_absent_faces},
          {"texels_lost_off_tiles", f.lost_off_tiles},
          {"texels_lost_tile_pool_full", f.lost_pool_full},
          {"config", config::to_json(spec.config)}};
}

}  // namespace arp::sim
