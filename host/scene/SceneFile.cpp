#include "SceneFile.hpp"

#include "Gallery.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "ModelImport.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "Primitives.hpp"
#include "common/InputError.hpp"
#include "common/PrintfText.hpp"
#include "common/ResourceUsage.hpp"
#include "common/StrictJson.hpp"

namespace arp::host {

using nlohmann::json;

namespace {

constexpr size_t kMaxNameChars = 256;  // a scene's or an object's name

// One JSON object read key by key; leftovers are unknown keys.
class Fields {
 public:
  Fields(const json& j, std::string source, std::string place) : j_(j), source_(std::move(source)), place_(std::move(place)) {
    if (!j.is_object()) fail("", "must be an object");
  }
  bool has(const char* k) const { return j_.contains(k); }
  double number(const char* k, double def, double lo, double hi) {
    seen_.insert(k);
    if (!j_.contains(k)) return def;
    const json& v = j_.at(k);
    if (!v.is_number()) fail(k, "must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) fail(k, "must be in [" + num(lo) + ", " + num(hi) + "]");
    return x;
  }
  int64_t integer(const char* k, int64_t def, int64_t lo, int64_t hi) {
    seen_.insert(k);
    if (!j_.contains(k)) return def;
    const json& v = j_.at(k);
    if (!v.is_number_integer()) fail(k, "must be a whole number, got " + brief(v));
    const bool huge = v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(INT64_MAX);
    const int64_t x = huge ? INT64_MAX : v.get<int64_t>();
    if (huge || x < lo || x > hi) fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + brief(v));
    return x;
  }
  glm::dvec3 vec3(const char* k, glm::dvec3 def, double lo, double hi) {
    seen_.insert(k);
    if (!j_.contains(k)) return def;
    const json& v = j_.at(k);
    if (!v.is_array() || v.size() != 3) fail(k, "must be an array of three numbers");
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) {
      if (!v[static_cast<size_t>(i)].is_number()) fail(k, "must be an array of three numbers");
      r[i] = v[static_cast<size_t>(i)].get<double>();
      if (!std::isfinite(r[i]) || r[i] < lo || r[i] > hi) fail(k, "elements must be in [" + num(lo) + ", " + num(hi) + "]");
    }
    return r;
  }
  std::string text(const char* k, const std::string& def) {
    seen_.insert(k);
    if (!j_.contains(k)) return def;
    if (!j_.at(k).is_string()) fail(k, "must be a string");
    return j_.at(k).get<std::string>();
  }
  // A name: written back into plans (memory.assignment) and quoted in messages, so of a bounded length.
  std::string name(const std::string& def) {
    std::string n = text("name", def);
    if (n.size() > kMaxNameChars)
      fail("name", "is " + std::to_string(n.size()) + " characters long; a name may have at most " + std::to_string(kMaxNameChars));
    return n;
  }
  const json* sub(const char* k) {
    seen_.insert(k);
    return j_.contains(k) ? &j_.at(k) : nullptr;
  }
  void finish() {
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (!seen_.count(it.key())) fail(it.key(), "unknown key");
  }
  [[noreturn]] void fail(const std::string& k, const std::string& why) const {
    throw InputError(source_, k.empty() ? place_ : (place_.empty() ? k : place_ + "." + k), why);
  }
  const std::string& place() const { return place_; }

 private:
  static std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
  }
  const json& j_;
  std::string source_, place_;
  std::set<std::string> seen_;
};

// A mesh's bytes as held.
int64_t bytes_of(const Mesh& m) {
  return static_cast<int64_t>(m.positions.size() * sizeof(m.positions[0]) + m.normals.size() * sizeof(m.normals[0]) +
                              m.uvs.size() * sizeof(m.uvs[0]) + m.indices.size() * sizeof(m.indices[0]));
}
// What the renderer holds of each drawn object during a render (CubeFaceRenderer: its vertices in the world, and
// their shades when Gouraud-shaded) -- per object, a model shared by several objects too. Mesh and copy together
// are what was measured: peak RSS of `arpsim frame --scene` grows 49 MB a flat 1024-segment sphere, whose mesh
// holds 37.8 MB and copy 12.6 MB (2026-11-29).
int64_t copy_bytes(const Mesh& m, bool smooth) {
  return static_cast<int64_t>(m.positions.size() * sizeof(glm::dvec3) * (smooth && !m.normals.empty() ? 2 : 1));
}
// The rest of a run (display memories, frames, the renderer's faces) needs room too: the meshes may take half.
constexpr int64_t kHeadroom = 2;

// A file the scene names under `key` (relative to the scene's folder), loaded once per path through `cache`:
// a failure is the file's own error (its file, its place, why) after the scene's place that names it. `shared`:
// whether an earlier object had loaded it.
template <class T, class Load>
std::shared_ptr<const T> named_file(const Fields& o, const char* key, const std::string& name, const std::string& base_dir,
                                    std::map<std::string, std::shared_ptr<const T>>& cache, Load load, bool* shared = nullptr) {
  std::string file = name;
  if (std::filesystem::path(file).is_relative()) file = (std::filesystem::path(base_dir) / file).string();
  auto it = cache.find(file);
  if (shared) *shared = it != cache.end();
  if (it == cache.end()) {
    std::shared_ptr<const T> loaded;
    try {
      loaded = std::make_shared<const T>(load(file));
    } catch (const InputError& e) {
      o.fail(key, e.what());
    }
    it = cache.emplace(file, std::move(loaded)).first;
  }
  return it->second;
}

}  // namespace

Scene scene_from_json(const json& j, const std::string& source, const std::string& base_dir) {
  Fields top(j, source, "");
  // "base": "gallery" -- the built-in gallery first, this file's objects added to it.
  const std::string base = top.text("base", "");
  if (!base.empty() && base != "gallery") top.fail("base", "must be \"gallery\" (the built-in scene) or absent");
  Scene s = base.empty() ? Scene{} : make_gallery();
  s.name = top.name(base.empty() ? "scene" : base);
  if (const json* ext = top.sub("extent")) {
    Fields e(*ext, source, "extent");
    s.extent_min = e.vec3("min", s.extent_min, -kWorldLimitM, kWorldLimitM);
    s.extent_max = e.vec3("max", s.extent_max, -kWorldLimitM, kWorldLimitM);
    e.finish();
    if (!(s.extent_min.x < s.extent_max.x && s.extent_min.y < s.extent_max.y && s.extent_min.z < s.extent_max.z))
      e.fail("", "min must be below max on every axis");
  }
  const json* objs = top.sub("objects");
  top.finish();
  if (!objs || !objs->is_array()) throw InputError(source, "objects", "must be an array (it may be empty)");
  std::map<std::string, std::shared_ptr<const Mesh>> models;  // one import per file
  std::map<std::string, std::shared_ptr<const RgbImage>> textures;
  const int64_t available = available_memory_bytes();
  int64_t mesh_bytes = 0;  // of the meshes made so far (a model shared by several objects once) and their copies
  for (size_t i = 0; i < objs->size(); ++i) {
    Fields o((*objs)[i], source, "objects[" + std::to_string(i) + "]");
    std::shared_ptr<const Mesh> mesh;
    bool shared = false;  // a model another object imported already
    int kinds = 0;
    for (const char* k : {"box", "quad", "cylinder", "sphere", "model"}) kinds += o.has(k) ? 1 : 0;
    if (kinds != 1) o.fail("", "needs exactly one of box, quad, cylinder, sphere, model");
    const int segments = static_cast<int>(o.integer("segments", 24, 3, 1024));
    if (o.has("box")) {
      mesh = std::make_shared<Mesh>(make_box(o.vec3("box", {1, 1, 1}, 1e-4, 1e5)));
    } else if (o.has("quad")) {
      const glm::dvec3 q = o.vec3("quad", {1, 1, 0}, 0, 1e5);
      if (q.x <= 0 || q.y <= 0) o.fail("quad", "width and height must be positive ([w, h, 0])");
      mesh = std::make_shared<Mesh>(make_quad(q.x, q.y));
    } else if (o.has("cylinder")) {
      const glm::dvec3 c = o.vec3("cylinder", {0.5, 1, 0}, 0, 1e5);
      if (c.x <= 0 || c.y <= 0) o.fail("cylinder", "radius and height must be positive ([r, h, 0])");
      mesh = std::make_shared<Mesh>(make_cylinder(c.x, c.y, segments));
    } else if (o.has("sphere")) {
      mesh = std::make_shared<Mesh>(make_sphere(o.number("sphere", 0.5, 1e-4, 1e5), segments));
    } else {
      const std::string file = o.text("model", "");
      if (file.empty()) o.fail("model", "is empty: name the model file (relative to the scene's folder)");
      mesh = named_file(o, "model", file, base_dir, models, [](const std::string& f) { return import_model(f); }, &shared);
    }
    if (mesh->indices.empty()) o.fail("", "the object has no triangles");
    Material mat;
    mat.color = o.vec3("color", mat.color, 0, 1);
    const std::string shading = o.text("shading", "flat");
    if (shading != "flat" && shading != "gouraud") o.fail("shading", "must be flat or gouraud");
    mat.smooth = shading == "gouraud";
    // A scene whose meshes (every object's own primitive, 1024 segments a sphere being a million triangles; a
    // model once) and the renderer's per-object copies would not fit: refused here, naming the object -- not a
    // failed allocation later.
    if (!shared) mesh_bytes += bytes_of(*mesh);
    mesh_bytes += copy_bytes(*mesh, mat.smooth);
    if (available > 0 && kHeadroom * mesh_bytes > available)
      o.fail("", "with this object the scene's meshes and the renderer's copies of them take " +
                     printf_text("%.1f", static_cast<double>(mesh_bytes) / 1e9) + " GB, more than half of the " +
                     printf_text("%.1f", static_cast<double>(available) / 1e9) + " GB this process has available; fewer objects or segments");
    const bool textured = o.has("texture");
    const std::string texture = o.text("texture", "");
    if (textured && texture.empty()) o.fail("texture", "is empty: name the image file, or leave the key out for no texture");
    if (textured) {
      if (mesh->uvs.empty()) o.fail("texture", "this shape has no texture coordinates (quads, boxes and models with them do)");
      mat.texture = named_file(o, "texture", texture, base_dir, textures, [](const std::string& f) { return read_rgb8(f); });
    }
    SceneObject& so = add_object(s, o.name("object " + std::to_string(i)), mesh,
                                 o.vec3("position", {0, 0, 0}, -kWorldLimitM, kWorldLimitM), mat);
    so.rotation_deg = o.vec3("rotation_deg", {0, 0, 0}, -3600, 3600);
    so.scale = o.vec3("scale", {1, 1, 1}, 1e-6, 1e6);
    // "size": scale the model uniformly so its bounding sphere has this diameter.
    const double size = o.number("size", 0, 0, 1e5);
    if (size > 0 && so.model_bound.radius > 0) so.scale = glm::dvec3(size / (2 * so.model_bound.radius));
    if (const json* sp = o.sub("spin")) {
      Fields f(*sp, source, o.place() + ".spin");
      so.animation.spin_axis = f.vec3("axis", {0, 1, 0}, -1, 1);
      so.animation.spin_deg_per_s = f.number("deg_per_s", 0, -36000, 36000);
      f.finish();
      if (glm::length(so.animation.spin_axis) == 0) f.fail("axis", "must not be zero");
    }
    if (const json* pa = o.sub("path")) {
      Fields f(*pa, source, o.place() + ".path");
      so.animation.path_speed = f.number("speed", 1, 0, 1e4);
      const json* pts = f.sub("points");
      f.finish();
      if (!pts || !pts->is_array() || pts->size() < 2) f.fail("points", "needs at least two [x, y, z] points");
      for (size_t k = 0; k < pts->size(); ++k) {
        const json& p = (*pts)[k];
        if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
          f.fail("points", "point " + std::to_string(k) + " must be [x, y, z]");
        so.animation.path.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
        const glm::dvec3& q = so.animation.path.back();
        if (std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}) > kWorldLimitM)
          f.fail("points", "point " + std::to_string(k) + " has a coordinate beyond +-" +
                               std::to_string(static_cast<int64_t>(kWorldLimitM)) + " m (the world's reach)");
      }
    }
    o.finish();
  }
  return s;
}

std::vector<std::string> scene_file_references(const std::string& path) {
  std::vector<std::string> out;
  try {
    const json j = parse_strict_json(read_input_file(path, 64 << 20, "scene file"), path);
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    const auto objs = j.find("objects");
    if (objs == j.end() || !objs->is_array()) return out;
    for (const json& o : *objs)
      for (const char* key : {"model", "texture"})
        if (o.is_object() && o.contains(key) && o[key].is_string()) {
          const std::filesystem::path f = o[key].get<std::string>();
          out.push_back((f.is_relative() ? dir / f : f).string());
        }
  } catch (const std::exception&) {
    out.clear();  // (the load reports it, naming the place)
  }
  return out;
}

Scene load_scene_file(const std::string& path) {
  const json j = parse_strict_json(read_input_file(path, 64 << 20, "scene file"), path);
  return scene_from_json(j, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace arp::host
