// A scene: objects made of meshes, each placed by position, rotation and
// scale, coloured, flat or Gouraud shaded, and optionally animated (spinning
// about an axis through its origin, or moving along a path). Metres and
// seconds; y up; the HMD's head frame looks down -z at yaw 0.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

#include "Mesh.hpp"
#include "common/Units.hpp"
#include "host/cubemap/CubeMapImages.hpp"

namespace arp::host {

struct Material {
  glm::dvec3 color{0.8, 0.8, 0.8};  // linear 0..1
  bool smooth = false;               // Gouraud (vertex normals) instead of flat
  std::shared_ptr<const RgbImage> texture;  // multiplies the colour where the mesh has texture coordinates
};

struct Animation {
  glm::dvec3 spin_axis{0, 1, 0};
  double spin_deg_per_s = 0;         // 0: no spin
  std::vector<glm::dvec3> path;      // empty: no path; else the object's position moves along it
  double path_speed = 0;             // m/s, looping
  bool animated() const { return spin_deg_per_s != 0 || (path.size() >= 2 && path_speed > 0); }
};

struct SceneObject {
  std::string name;
  std::shared_ptr<const Mesh> mesh;
  Sphere model_bound;                // of the mesh, model frame
  glm::dvec3 position{0.0};
  glm::dvec3 rotation_deg{0.0};      // yaw (about y), pitch (about x), roll (about z), applied in that order
  glm::dvec3 scale{1.0};
  Material material;
  Animation animation;

  glm::dmat4 model_at(double t_s) const;
  // World-space bounding sphere at time t.
  Sphere world_bound(double t_s) const;
  glm::dvec3 position_at(double t_s) const;
};

// How far from the origin objects, eyes, walks and traced heads may be (common/Units.hpp).
using arp::kWorldLimitM;

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  glm::dvec3 extent_min{-50.0}, extent_max{50.0};
  std::vector<std::string> notes;  // e.g. exhibits replaced because a model package is not installed
  size_t triangles() const;
};

// What the scene is, as a number (common/Fingerprint over every object's name,
// placement, material, animation and mesh; 63 bits, never 0): the scene a plan
// was made for (plan.scene_hash).
int64_t scene_hash(const Scene& s);

// Adds an object with a shared mesh; computes its bound.
SceneObject& add_object(Scene& s, std::string name, std::shared_ptr<const Mesh> mesh, const glm::dvec3& position,
                        const Material& material);

}  // namespace arp::host
