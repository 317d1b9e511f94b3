// The in-process half of model import: a model file read by assimp (every
// mesh, node transforms applied, triangulated, merged into one). It runs in
// the watched helper process `arpsim-import` (apps/import), never in arpsim
// itself: assimp hangs, aborts or exhausts memory on some broken files
// (host/scene/ModelImport guards against that).
#pragma once
#include <string>

#include "Mesh.hpp"

namespace arp::host {

// Positions, texture coordinates and indices as assimp gives them (not yet
// checked); InputError naming the file when assimp refuses it.
Mesh assimp_import(const std::string& path);

}  // namespace arp::host
