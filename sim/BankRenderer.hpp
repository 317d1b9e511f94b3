// The renderer a run draws scenes with (--renderer): "software", the
// deterministic reference (host::CubeFaceRenderer), or "gl", OpenGL through EGL
// (host::GlCubeRenderer: the GPU when the machine has one, llvmpipe otherwise).
#pragma once
#include <string>

#include "MemoryContents.hpp"
#include "host/priority/HostSimulation.hpp"

namespace arp::sim {

constexpr const char* kRendererNames = "software or gl";

// InputError naming --renderer: an unknown name, or a renderer other than the default with no scene to draw.
void check_renderer(const MemoryContents& m);

// InputError naming --renderer for an unknown name, or when OpenGL cannot be had (the reason from EGL).
host::HostSimulation::BankRenderer make_bank_renderer(const std::string& name);

}  // namespace arp::sim
