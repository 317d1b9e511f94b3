// The mesh's wire format between the model importer helper (apps/import)
// and arpsim (host/scene/ModelImport): a magic, then positions, texture
// coordinates and indices, each a 64-bit count and the raw values.
#pragma once
#include <string>

#include "Mesh.hpp"

namespace arp::host {

// The mesh as bytes for the pipe, and back (InputError naming `source` for a
// truncated or corrupt stream; the counts are checked against the bytes
// before anything is allocated).
std::string encode_mesh(const Mesh& m);
Mesh decode_mesh(const std::string& bytes, const std::string& source);

}  // namespace arp::host
