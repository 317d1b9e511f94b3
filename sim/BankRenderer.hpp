// The renderer a run draws scenes with (--renderer): "software", the
// deterministic reference (host::CubeFaceRenderer), or "gl", OpenGL through EGL
// (host::GlCubeRenderer: the GPU when the machine has one, llvmpipe otherwise).
#pragma once
#include <string>

#include "MemoryContents.hpp"
#include "host/priority/HostSimulation.hpp"

namespace arp::sim {

constexpr const char* kRendererNames = "software or gl";

// InputError naming --renderer: an unknown name, a renderer other than the default with no scene to
// draw, or GL with depth codes wider than it computes exactly (memory.depth_bits); --no-face-culling
// with no scene.
void check_renderer(const MemoryContents& m, int depth_bits);

// The renderer named, drawing on `threads` threads (0: every core; the software renderer's faces, GL's
// conversion into memory words -- the run's --threads), culling objects to the faces they reach unless
// `face_culling` is off (--no-face-culling). InputError naming --renderer for an unknown name, or when
// OpenGL cannot be had (the reason from EGL), then or at a later draw.
host::HostSimulation::BankRenderer make_bank_renderer(const std::string& name, int threads, bool face_culling = true);

}  // namespace arp::sim
