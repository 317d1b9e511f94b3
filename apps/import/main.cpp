// arpsim-import: the helper process arpsim reads model files through
// (host/scene/ModelImport). It imports one file with assimp and writes the
// mesh to stdout in arpsim's wire format; an unreadable file is a message on
// stderr and exit status 2. arpsim watches it: whatever a broken file does
// to the importer (hang, abort, memory) stays in this process.
#include <cstdio>
#include <exception>
#include <string>

#include "common/InputError.hpp"
#include "host/scene/AssimpImport.hpp"
#include "host/scene/MeshWire.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: arpsim-import MODEL_FILE  (run by arpsim; writes the mesh to stdout)\n");
    return 2;
  }
  try {
    const std::string bytes = arp::host::encode_mesh(arp::host::assimp_import(argv[1]));
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0) return 3;
    return 0;
  } catch (const arp::InputError& e) {
    std::fprintf(stderr, "arpsim-import: error: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arpsim-import: error: %s: %s\n", argv[1], e.what());
  }
  return 2;
}
