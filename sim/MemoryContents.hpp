// What fills the display memories for a run without a host simulation: a
// cube map from files (six faces, a cross, an equirectangular panorama), a
// scene rendered once from the head's position, or the calibration pattern.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/OutputPaths.hpp"

#include "host/cubemap/CubeMapImages.hpp"
#include "host/scene/Scene.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::sim {

struct MemoryContents {
  std::string faces, cross, equirect;  // at most one: a cube map from files
  std::string scene;                   // or a scene file / "gallery"
  std::string position;                // --scene: head position x,y,z (default: the gallery walk's start)
  // Absent: not given (0 s; dp::kDefaultIpdM) -- given, they need a scene, even at their default values.
  std::optional<double> time_s;        // --scene: animation time
  std::optional<double> ipd_m;         // distance between the eyes
  std::string renderer = "software";   // --renderer: what draws a scene, here and in the host (sim/BankRenderer)
  bool face_culling = true;            // not --no-face-culling: each object drawn only on the faces it reaches
  // The scene and the eyes the configuration was planned for (plan.scene_hash, 0: none; plan.ipd_m) and the
  // configuration's name: load_scene() warns once when the scene is another, or the eyes are another distance apart
  // (expect_plan sets them).
  int64_t plan_scene_hash = 0;
  double plan_ipd_m = dp::kDefaultIpdM;
  int plan_eyes = 2;
  bool plan_bounds_drawing = false;  // faces or tiles left out (memory.faces, memory.tiles): wider eyes lose texels there
  // memory.assignment: unused here (a scene is drawn whole into memory 0), but its names are checked against the scene
  // as a run checks them -- not by regions (memory.region_size_m), which place every object themselves.
  std::vector<dp::ObjectAssignment> plan_assignment;
  std::string plan_source;
  void expect_plan(const dp::ArpConfig& c, const std::string& source) {
    plan_scene_hash = c.plan.scene_hash;
    std::string why;  // (a configuration resolved is valid: its assignment parses)
    plan_assignment.clear();
    if (c.memory.region_size_m == 0) dp::object_assignments(c.memory, plan_assignment, why);
    plan_ipd_m = c.plan.ipd_m;
    plan_eyes = c.timing.eyes;
    plan_bounds_drawing = !c.memory.tiles.empty() || c.memory.faces_present() < 6;
    plan_source = source;
  }

  // The cube map chosen, at face size S; `source` names it for messages.
  host::CubeMapImages load(int face_size, std::string& source) const;
  // Fills memory 0 of every eye and swaps it in: the cube map, or the scene
  // rendered from each eye's position (head orientation `head`) on `threads` threads (0: every core).
  void fill(dp::DisplayMemorySet& mem, const dp::Quat& head, std::string& source, int threads = 0) const;
  // The scene named by `scene` (notes about stand-ins, and a plan made for another scene, go to stderr).
  host::Scene load_scene() const;
  double time() const { return time_s.value_or(0.0); }
  // ipd_m (or the default), checked: InputError naming --ipd unless 0 .. 1 m. Every user of the eyes' distance (the memories filled
  // here, a walk's host, a plan) takes it through this.
  double checked_ipd_m() const;
  // The files these contents read, named by their options (a scene's models and textures too): the inputs no
  // output may overwrite (check_output_paths).
  std::vector<NamedPath> input_files() const;
};

// memory.assignment's names no object of `scene` has (`unknown`): an error naming `source` in a configuration
// planned for this scene or for none (plan.scene_hash `plan_scene_hash`, 0: none), a warning where it was planned
// for another (said once, as the scene is).
void check_assignment_names(const std::vector<std::string>& unknown, const host::Scene& scene, int64_t plan_scene_hash,
                            const std::string& source);

}  // namespace arp::sim
