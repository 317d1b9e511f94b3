// Golden reference of the ARP pixel path: double precision with GLM, written
// independently of rtl_model/datapath (it includes only its configuration
// structs and reads texels through the display memory's storage API). It
// says what is *right*: exact directions, exact rotation, exact face and
// texel selection (same documented tie rule), exact bilinear filtering.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::golden {

// Exact lens-corrected unit direction of active pixel (x, y) of `eye`, head frame.
glm::dvec3 lens_direction(const dp::ArpConfig& c, int eye, int x, int y);

glm::dmat3 rotation(const glm::dquat& q);  // normalises q

struct Address {
  int face;   // 0..5: +X -X +Y -Y +Z -Z
  double u, v;  // texel-space position s*S, t*S in [0, S]
  int x, y;   // nearest texel: floor(u), floor(v) clamped to the face
};

Address address(const glm::dvec3& d, int face_size);

// Position of direction d on the plane of `face` (u, v may lie outside [0, S]);
// false if d points away from that face.
bool project_onto_face(const glm::dvec3& d, int face, int face_size, double& u, double& v);

// Composited colour of the memories' front buffers at an address, per
// channel in display units (0 .. 2^display_bits - 1), not rounded.
glm::dvec3 sample(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem, int eye, const Address& a, bool bilinear);

// A whole frame at one orientation: colours per pixel, [eye][y][x].
std::vector<glm::dvec3> frame(const dp::ArpConfig& c, const dp::DisplayMemorySet& mem, const glm::dquat& q);

}  // namespace arp::golden
