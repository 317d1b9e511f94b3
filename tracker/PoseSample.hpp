// A timed head pose from any tracker source. Frames: the head frame is x
// right, y up, looking down -z (as in the pipeline); the orientation rotates
// head-frame directions into the world frame. Units: picoseconds, metres,
// radians per second. The tracker library never includes SystemC or the pipeline.
#pragma once
#include <cstdint>
#include <string>
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

// Pose times given in double seconds (trace files, synthetic motion) stay
// within +-kPoseTimeLimitS: the int64 picosecond timeline spans +-106 days,
// and a double still resolves a microsecond there.
constexpr double kPoseTimeLimitS = 9e6;
// The fastest tracker arpsim models, in samples a second (synthetic motion's
// --hz, the laboratory's tracker model). A trace read holding more than that
// many samples beyond as many a second of its span is refused (a guard on the
// memory a stream can take, not a test of its rate: its warnings say that).
constexpr double kMaxSampleRateHz = 1e6;
// The limit as the messages state it: "9e6 s (104 days)".
inline std::string pose_time_limit_text() {
  return std::to_string(static_cast<int>(kPoseTimeLimitS / 1e6)) + "e6 s (" + std::to_string(static_cast<int>(kPoseTimeLimitS / 86400)) +
         " days)";
}

}  // namespace arp::tracker
