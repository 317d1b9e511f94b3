// A walking path: a polyline of head positions walked at constant speed
// (default 1 m/s, as in Chow 2005), looping; stereo eye positions from the
// head orientation and the interpupillary distance.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace arp::host {

class WalkPath {
 public:
  WalkPath() = default;
  // InputError naming `source` for fewer than two points, a zero-length path, or a speed outside
  // 0 .. 1000 m/s (0: standing at the first point).
  WalkPath(std::vector<glm::dvec3> points, double speed_m_s, const std::string& source);
  static WalkPath standing(const glm::dvec3& at);  // no motion at all

  glm::dvec3 position(double t_s) const;
  glm::dvec3 velocity(double t_s) const;
  // The way the walker faces at t: turned about +y toward where it goes (yaw 0 looks down -z, positive turns
  // left), on which a run's head motion turns. Standing, yaw atan2(-0, -0).
  glm::dquat facing(double t_s) const;
  double speed() const { return speed_; }
  double length() const { return length_; }
  const std::vector<glm::dvec3>& points() const { return points_; }

 private:
  double distance_at(double t_s) const;           // along the path, 0 .. length (it loops)
  glm::dvec3 at_distance(double d_m) const;

  std::vector<glm::dvec3> points_;
  std::vector<double> cumulative_;
  double speed_ = 0, length_ = 0;
};

// The head's mean angular speed over the time dt_s before t_s, rad/s: the angle between its orientations then
// and at t_s, over dt_s. What the priority rule takes the head to keep turning at (host::EyeTurn), in the run
// (from the head it is shown) and in the plan (from the walk's facing) alike.
double turn_rate_rad_s(const std::function<glm::dquat(double)>& head, double t_s, double dt_s);
// The same for a head that only faces where the walk goes (WalkPath::facing, exact at any time), over the part of
// the dt_s before t_s that is at or after start_s (0 when none is): a run with no head motion of its own takes it
// from the run's start, its plan from the motion's, so both see the same turning (before its start a walk is at
// its end: an open one a jump away).
double facing_turn_rate_rad_s(const WalkPath& walk, double t_s, double dt_s, double start_s);

// Eye `eye` of `eyes` (0 = left) at head position p with orientation q.
glm::dvec3 eye_position(const glm::dvec3& head, const glm::dquat& q, int eye, int eyes, double ipd_m);

// A path file: {"speed": 1.0, "points": [[x,y,z], ...]} (metres, m/s).
WalkPath load_walk_file(const std::string& path);
// The same from parsed JSON ({"speed": m/s, "points": [[x, y, z], ...]}); `path` names it in errors.
WalkPath walk_from_json(const nlohmann::json& j, const std::string& path);

// A fingerprint of the motion a walk makes (its points and speed), for
// recognising the walk a configuration was planned for (plan.motion_hash).
// Never 0.
int64_t walk_hash(const WalkPath& w);

}  // namespace arp::host
