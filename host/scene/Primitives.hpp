// Procedural meshes in metres, centred on the origin (y up), outward normals
// implied by counter-clockwise winding seen from outside.
#pragma once
#include "Mesh.hpp"

namespace arp::host {

Mesh make_box(const glm::dvec3& size);
Mesh make_quad(double width, double height);  // in the x-y plane, facing +z
Mesh make_cylinder(double radius, double height, int segments);  // axis y
Mesh make_sphere(double radius, int segments);

}  // namespace arp::host
