// The simulated rendering engine's speed: how long a render takes, from what
// it drew -- never the wall-clock time of our own code, so runs are
// deterministic. Its rates are the configuration's host.* keys
// (dp::HostEngineConfig, where the defaults and their reason live).
#pragma once
#include "host/render/CubeFaceRenderer.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::host {

struct RenderEngine : dp::HostEngineConfig {
  RenderEngine() = default;
  explicit RenderEngine(const dp::HostEngineConfig& c) : dp::HostEngineConfig(c) {}
  double seconds(const RenderStats& s) const {
    return static_cast<double>(s.objects) * object_setup_s + static_cast<double>(s.triangles) / triangles_per_s +
           static_cast<double>(s.texels_filled) / texels_per_s;
  }
};

}  // namespace arp::host
