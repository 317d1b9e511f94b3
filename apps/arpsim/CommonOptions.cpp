#include "CommonOptions.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sim/ConfigFile.hpp"
#include "common/AtomicFile.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/SceneFile.hpp"
#include "host/motion/WalkPath.hpp"
#include <glm/gtc/quaternion.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>
#include "common/InputError.hpp"

namespace arp::app {

void ConfigOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--config", file, "JSON configuration file (every key: docs/configuration.md)");
  cmd.add_option("--set", sets, "Override one key, e.g. --set datapath.vec_frac=12 (repeatable)")
      ->type_name("SECTION.KEY=VALUE");
}

dp::ArpConfig ConfigOptions::resolve() const {
  dp::ArpConfig c;
  if (!file.empty()) c = config::load_file(file, c);
  if (!sets.empty()) c = config::apply_overrides(c, sets);
  config::check(c, file.empty() ? "configuration" : file);
  return c;
}

void CubeMapOptions::add_to(CLI::App& cmd) {
  auto* g = cmd.add_option_group("cube map", "Display memory contents (default: the calibration pattern)");
  g->add_option("--faces", faces, "Folder with px nx py ny pz nz.<ext>, each face_size square");
  g->add_option("--cross", cross, "One image, a 4:3 horizontal or 3:4 vertical cross");
  g->add_option("--equirect", equirect, "One 2:1 equirectangular panorama");
  g->add_option("--scene", scene, "Render a scene into the memories: a scene file (docs/host.md) or 'gallery'");
  g->require_option(0, 1);
  cmd.add_option("--position", position, "--scene: head position x,y,z in metres (default: the gallery walk's start)");
  cmd.add_option("--time", time_s, "--scene: scene time in seconds (animations)")->capture_default_str();
  cmd.add_option("--ipd", ipd_m, "--scene: distance between the eyes, metres")->capture_default_str();
}

void CubeMapOptions::fill(dp::DisplayMemorySet& mem, const dp::Quat& head, std::string& source) const {
  if (scene.empty()) {
    if (!position.empty()) throw InputError("--position", "", "only with --scene");
    host::load_into_memories(mem, 0, load(mem.format().face_size, source), host::far_depth(mem.format()));
    return;
  }
  if (!std::isfinite(time_s) || std::abs(time_s) > 1e7) throw InputError("--time", "", "must be finite, within 1e7 s");
  if (!(ipd_m >= 0) || ipd_m > 1) throw InputError("--ipd", "", "must be 0 .. 1 m");
  const host::Scene sc = scene == "gallery" ? host::make_gallery() : host::load_scene_file(scene);
  for (const auto& n : sc.notes) std::fprintf(stderr, "arpsim: note: %s\n", n.c_str());
  glm::dvec3 p = host::gallery_walk().front();
  if (!position.empty()) {
    std::stringstream ss(position);
    char c1 = 0, c2 = 0;
    if (!(ss >> p.x >> c1 >> p.y >> c2 >> p.z) || c1 != ',' || c2 != ',' || !ss.eof() || !std::isfinite(p.x) ||
        !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError("--position", position, "expected three finite numbers x,y,z");
  }
  const glm::dquat q(head.w, head.x, head.y, head.z);
  const host::CubeFaceRenderer renderer;
  for (int e = 0; e < mem.eyes(); ++e) {
    dp::DisplayMemoryBank& bank = mem.bank(e, 0);
    renderer.render(sc, {}, time_s, host::eye_position(p, q, e, mem.eyes(), ipd_m), bank);
    bank.vblank();
  }
  source = "scene " + sc.name + " (" + std::to_string(sc.objects.size()) + " objects, " +
           std::to_string(sc.triangles()) + " triangles)";
}

host::CubeMapImages CubeMapOptions::load(int S, std::string& source) const {
  if (!faces.empty()) { source = faces; return host::load_six_faces(host::six_face_paths_in(faces), S); }
  if (!cross.empty()) { source = cross; return host::load_cross(cross, S); }
  if (!equirect.empty()) { source = equirect; return host::load_equirect(equirect, S); }
  source = "calibration pattern";
  return host::make_calibration_pattern(S);
}

void write_text_atomic(const std::string& path, const std::string& text) {
  const auto tmp = temp_path_beside(path);
  std::ofstream out(tmp, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    discard_temp_file(tmp);
    throw InputError(path, "", "cannot write the file");
  }
  commit_temp_file(tmp, path);
}

}  // namespace arp::app
