// The simulated rendering engine's speed: how long a render takes, from what
// it drew -- never the wall-clock time of our own code, so runs are
// deterministic. Defaults: this project's assumption of a modest engine
// (docs/host.md) that renders the whole default gallery, both eyes, at
// 60 Hz with a little headroom, so the baseline is not overloaded.
#pragma once
#include "host/render/CubeFaceRenderer.hpp"

namespace arp::host {

struct RenderEngine {
  double triangles_per_s = 50e6;   // triangle set-up rate (per face a triangle is sent to)
  double pixels_per_s = 1e9;       // fill rate (texels passing the depth test)
  double object_setup_s = 5e-6;    // per object drawn (state changes, transforms)
  double seconds(const RenderStats& s) const {
    return static_cast<double>(s.objects) * object_setup_s + static_cast<double>(s.triangles) / triangles_per_s +
           static_cast<double>(s.texels_filled) / pixels_per_s;
  }
};

}  // namespace arp::host
