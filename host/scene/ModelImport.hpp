// Meshes from model files (OBJ, PLY, OFF, STL, glTF/GLB, 3DS, Collada, ...),
// imported so that no file can take arpsim down: the header's element counts
// are checked against the file's size first (host/scene/ModelPrecheck), then
// assimp reads it in a helper process, `arpsim-import` (exec'd, not forked),
// whose time and resident memory are watched; past a limit it is killed. A
// hang, an abort or a runaway allocation in the importer becomes an
// InputError naming the file. The mesh that comes back is checked (finite
// coordinates, indices in range) and given smooth normals.
#pragma once
#include <cstdint>
#include <string>

#include "Mesh.hpp"

namespace arp::host {

struct ImportLimits {
  double seconds = 60;                    // the importer's wall-clock time
  uint64_t max_bytes = uint64_t{3} << 30;  // its resident memory
  // The defaults, or ARPSIM_IMPORT_SECONDS and ARPSIM_IMPORT_MAX_MB.
  static ImportLimits from_environment();
};

Mesh import_model(const std::string& path, const ImportLimits& limits = ImportLimits::from_environment());

}  // namespace arp::host
