// Before a model file goes to the importer: the element counts its header
// declares, checked against the bytes the file holds, for the formats arpsim
// documents -- PLY, OFF, STL (binary), glTF/GLB. A header promising 10^9
// vertices in a file of a kilobyte is refused here, in microseconds, instead
// of growing the importer to gigabytes. OBJ has no counts: it, and every other
// format assimp reads, goes through the importer's guard only
// (host/scene/ModelImport). InputError naming the file, the place and the reason.
#pragma once
#include <cstdint>
#include <string>

namespace arp::host {

// The largest model file arpsim reads.
constexpr uint64_t kMaxModelBytes = uint64_t{1} << 30;

void precheck_model(const std::string& path);

}  // namespace arp::host
