// A timed head pose from any tracker source. Frames: the head frame is x
// right, y up, looking down -z (as in the pipeline); the orientation rotates
// head-frame directions into the world frame. Units: picoseconds, metres,
// radians per second. The tracker library never includes SystemC or the pipeline.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace arp::tracker {

struct PoseSample {
  int64_t time_ps = 0;
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // unit, head -> world
  bool has_position = false;
  glm::dvec3 position{0.0};                   // metres, world frame
  bool has_angular_velocity = false;
  glm::dvec3 angular_velocity{0.0};           // rad/s, head frame
};

}  // namespace arp::tracker
