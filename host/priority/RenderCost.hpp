// The simulated rendering engine's speed: how long a render takes, from what
// it drew -- never the wall-clock time of our own code, so runs are
// deterministic. Defaults: a mid-1990s class engine (this project's
// assumption; docs/host.md).
#pragma once
#include "host/render/CubeFaceRenderer.hpp"

namespace arp::host {

struct RenderEngine {
  double triangles_per_s = 10e6;   // triangle set-up rate (per face a triangle is sent to)
  double pixels_per_s = 200e6;     // fill rate (texels passing the depth test)
  double object_setup_s = 5e-6;    // per object drawn (state changes, transforms)
  double seconds(const RenderStats& s) const {
    return static_cast<double>(s.objects) * object_setup_s + static_cast<double>(s.triangles) / triangles_per_s +
           static_cast<double>(s.texels_filled) / pixels_per_s;
  }
};

}  // namespace arp::host
