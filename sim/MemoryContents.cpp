#include "MemoryContents.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/InputError.hpp"
#include "common/PrintfText.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/PriorityScheduler.hpp"
#include "BankRenderer.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/SceneFile.hpp"

namespace arp::sim {

double MemoryContents::checked_ipd_m() const {
  const double d = ipd_m.value_or(dp::kDefaultIpdM);
  if (!(d >= 0) || d > 1) throw InputError("--ipd", printf_text("%g", d), "must be 0 .. 1 m");
  return d;
}

void MemoryContents::fill(dp::DisplayMemorySet& mem, const dp::Quat& head, std::string& source, int threads) const {
  check_renderer(*this, mem.format().depth_bits);
  if (scene.empty()) {
    if (!position.empty()) throw InputError("--position", "", "only with --scene");
    // (a cube map's images are the same for both eyes and have no time: given, these changed nothing)
    if (time_s) throw InputError("--time", "", "only with --scene (the time of its animations)");
    if (ipd_m) throw InputError("--ipd", "", "only with --scene (a cube map's image is the same for both eyes)");
    host::load_into_memories(mem, 0, load(mem.format().face_size, source), host::far_depth(mem.format()));
    return;
  }
  if (!std::isfinite(time()) || std::abs(time()) > 1e7) throw InputError("--time", "", "must be finite, within 1e7 s");
  const double ipd = checked_ipd_m();
  const host::Scene sc = load_scene();
  check_assignment_names(host::unknown_assignment_names(sc, plan_assignment), sc, plan_scene_hash, plan_source);
  glm::dvec3 p = host::gallery_walk().front();
  if (!position.empty()) {
    std::stringstream ss(position);
    char c1 = 0, c2 = 0;
    if (!(ss >> p.x >> c1 >> p.y >> c2 >> p.z) || c1 != ',' || c2 != ',' || !ss.eof() || !std::isfinite(p.x) ||
        !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError("--position", position, "expected three finite numbers x,y,z");
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > host::kWorldLimitM)
      throw InputError("--position", position, "a coordinate beyond ±" + std::to_string(static_cast<int64_t>(host::kWorldLimitM)) +
                                                    " m, the farthest a view is supported (docs/accuracy.md)");
  }
  const glm::dquat q(head.w, head.x, head.y, head.z);
  const auto render = make_bank_renderer(renderer, threads, face_culling);
  for (int e = 0; e < mem.eyes(); ++e) {
    dp::DisplayMemoryBank& bank = mem.bank(e, 0);
    render(sc, {}, time(), host::eye_position(p, q, e, mem.eyes(), ipd), bank, nullptr);
    bank.vblank();
  }
  source = "scene " + sc.name + " (" + std::to_string(sc.objects.size()) + " objects, " +
           std::to_string(sc.triangles()) + " triangles)";
}

host::CubeMapImages MemoryContents::load(int S, std::string& source) const {
  if (!faces.empty()) { source = faces; return host::load_six_faces(host::six_face_paths_in(faces), S); }
  if (!cross.empty()) { source = cross; return host::load_cross(cross, S); }
  if (!equirect.empty()) { source = equirect; return host::load_equirect(equirect, S); }
  source = "calibration pattern";
  return host::make_calibration_pattern(S);
}

std::vector<NamedPath> MemoryContents::input_files() const {
  std::vector<NamedPath> in = {{"--cross", cross}, {"--equirect", equirect}};
  if (scene.empty() || scene == "gallery") return in;
  in.push_back({"--scene", scene});
  for (const std::string& f : host::scene_file_references(scene)) in.push_back({"model or texture of --scene " + scene, f});
  return in;
}

host::Scene MemoryContents::load_scene() const {
  host::Scene sc = scene == "gallery" ? host::make_gallery() : host::load_scene_file(scene);
  for (const auto& n : sc.notes) std::fprintf(stderr, "arpsim: note: %s\n", n.c_str());
  if (plan_scene_hash != 0) {
    const int64_t h = host::scene_hash(sc);
    if (h != plan_scene_hash)
      std::fprintf(stderr, "arpsim: warning: %s was planned for another scene (plan.scene_hash %lld); scene %s hashes to %lld: "
                           "run `arpsim plan` for it\n",
                   plan_source.c_str(), static_cast<long long>(plan_scene_hash), sc.name.c_str(), static_cast<long long>(h));
    // The plan bounded its faces and tiles for an object's sphere grown by half the eyes' distance, and counted the
    // engine's load for those eyes. (One eye has no distance. Within a nanometre: a value a hand or a tool rewrote.)
    const double ipd = checked_ipd_m();
    if (plan_eyes > 1 && std::abs(ipd - plan_ipd_m) > 1e-9)
      std::fprintf(stderr, "arpsim: warning: %s was planned for eyes %g mm apart (plan.ipd_m %g); this run's --ipd is %g mm: "
                           "its faces and tiles were bounded for the planned eyes%s (run `arpsim plan` with --ipd %g)\n",
                   plan_source.c_str(), 1000 * plan_ipd_m, plan_ipd_m, 1000 * ipd,
                   ipd > plan_ipd_m && plan_bounds_drawing ? ": wider ones can draw outside them, and those texels are lost" : "", ipd);
  }
  return sc;
}

void check_assignment_names(const std::vector<std::string>& unknown, const host::Scene& scene, int64_t plan_scene_hash,
                            const std::string& source) {
  if (unknown.empty()) return;
  std::string names;
  for (size_t i = 0; i < unknown.size() && i < 5; ++i) names += (i ? ", \"" : "\"") + quoted(unknown[i]) + "\"";  // (a name can be megabytes long)
  if (unknown.size() > 5) names += " and " + std::to_string(unknown.size() - 5) + " more";
  const std::string what = std::to_string(unknown.size()) + " of its names are no object of scene " + quoted(scene.name) + ": " + names;
  if (plan_scene_hash == 0 || plan_scene_hash == host::scene_hash(scene)) throw InputError(source, "memory.assignment", what);
  std::fprintf(stderr, "arpsim: warning: %s: memory.assignment: %s (the plan was made for another scene; those strings are not used)\n",
               source.c_str(), what.c_str());
}

}  // namespace arp::sim
