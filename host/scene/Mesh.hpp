// A triangle mesh in its own model frame: positions, optional per-vertex
// normals (for Gouraud shading), indices three per triangle.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace arp::host {

struct Mesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // empty, or one per position
  std::vector<glm::dvec2> uvs;      // empty, or one per position: texture coordinates (v = 1 at the image's top)
  std::vector<uint32_t> indices;    // three per triangle
  size_t triangles() const { return indices.size() / 3; }
};

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};

// A sphere holding every vertex (centre of the bounding box, largest distance).
Sphere bounding_sphere(const Mesh& m);

// Every coordinate finite, every index in range, a whole number of triangles,
// normals absent or one per vertex; InputError naming `source` and the first fault.
void check_mesh(const Mesh& m, const std::string& source);

// Smooth normals: the area-weighted average of the faces around each vertex.
void compute_vertex_normals(Mesh& m);

}  // namespace arp::host
