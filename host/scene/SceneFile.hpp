// The scene file (JSON; docs/host.md): a name, the world extent, and
// objects -- a primitive (box, quad, cylinder, sphere) or a model file
// (assimp), placed, coloured, shaded, optionally spinning or moving along a
// path. Strict: an unknown key, a wrong type or a value out of range is an
// InputError naming the file and the object's key.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "Scene.hpp"

namespace arp::host {

Scene load_scene_file(const std::string& path);
// `base_dir` resolves relative model paths; `source` names the text in errors.
Scene scene_from_json(const nlohmann::json& j, const std::string& source, const std::string& base_dir);
// The files a scene file names (its objects' "model" and "texture", resolved as the loader resolves them), for the
// check that no output overwrites one; nothing where the file cannot be read or parsed (loading it says why).
std::vector<std::string> scene_file_references(const std::string& path);

}  // namespace arp::host
