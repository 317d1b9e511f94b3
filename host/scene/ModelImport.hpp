// Meshes from model files through assimp (OBJ, PLY, glTF, 3DS, Collada, ...):
// every mesh of the file, node transforms applied, triangulated, merged into
// one; then checked (finite coordinates, indices in range). A file assimp
// cannot read, or a broken model, is an InputError naming the file and why.
#pragma once
#include <string>

#include "Mesh.hpp"

namespace arp::host {

Mesh import_model(const std::string& path);

}  // namespace arp::host
