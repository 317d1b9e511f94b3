#include "WalkPath.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/Fingerprint.hpp"
#include "common/InputError.hpp"
#include "host/scene/Scene.hpp"
#include "common/StrictJson.hpp"

namespace arp::host {

WalkPath::WalkPath(std::vector<glm::dvec3> points, double speed, const std::string& source) : points_(std::move(points)), speed_(speed) {
  if (points_.size() < 2) throw InputError(source, "points", "a walk needs at least two points");
  // 0 m/s is a viewer standing at the path's first point: the baseline with no translation.
  if (!(speed_ >= 0) || speed_ > 1000) throw InputError(source, "speed", "must be 0 .. 1000 m/s");
  for (size_t i = 0; i < points_.size(); ++i) {
    const auto& p = points_[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(source, "points[" + std::to_string(i) + "]", "not finite");
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kWorldLimitM)
      throw InputError(source, "points[" + std::to_string(i) + "]",
                       "a coordinate beyond ±" + std::to_string(static_cast<int64_t>(kWorldLimitM)) + " m");
  }
  cumulative_.push_back(0);
  for (size_t i = 1; i < points_.size(); ++i) {
    length_ += glm::length(points_[i] - points_[i - 1]);
    cumulative_.push_back(length_);
  }
  if (!(length_ > 0)) throw InputError(source, "points", "the path has zero length");
}

WalkPath WalkPath::standing(const glm::dvec3& at) {
  WalkPath w;
  w.points_ = {at};
  w.cumulative_ = {0};
  return w;
}

glm::dvec3 WalkPath::position(double t) const {
  if (points_.size() < 2 || speed_ <= 0) return points_.empty() ? glm::dvec3(0) : points_.front();
  return at_distance(distance_at(t));
}

double WalkPath::distance_at(double t) const {
  double d = std::fmod(speed_ * t, length_);
  if (d < 0) d += length_;
  return d;
}

glm::dvec3 WalkPath::at_distance(double d) const {
  size_t i = 1;
  while (i + 1 < cumulative_.size() && cumulative_[i] < d) ++i;
  const double seg = cumulative_[i] - cumulative_[i - 1];
  const double f = seg > 0 ? (d - cumulative_[i - 1]) / seg : 0.0;
  return points_[i - 1] + (points_[i] - points_[i - 1]) * f;
}

glm::dvec3 WalkPath::velocity(double t) const {
  if (points_.size() < 2 || speed_ <= 0) return glm::dvec3(0);
  const double dt = 1e-3;
  glm::dvec3 v;
  if (points_.front() == points_.back()) {
    v = (position(t + dt) - position(t - dt)) / (2 * dt);  // a loop: round its closing point as round any corner
  } else {
    // An open path jumps from its end back to its start: the difference stays on one side of the jump (across
    // it, the walker would face back along the path for a millisecond either side, its eyes swapped).
    const double d = distance_at(t), step = speed_ * dt;
    v = at_distance(std::min(d + step, length_)) - at_distance(std::max(d - step, 0.0));
  }
  const double l = glm::length(v);
  return l > 0 ? v * (speed_ / l) : v;  // corners: the speed, in the averaged direction
}

glm::dquat WalkPath::facing(double t) const {
  const glm::dvec3 v = velocity(t);
  const double yaw = std::atan2(-v.x, -v.z);
  return glm::angleAxis(yaw, glm::dvec3(0, 1, 0));
}

double turn_rate_rad_s(const std::function<glm::dquat(double)>& head, double t, double dt) {
  const glm::dquat a = head(t - dt), b = head(t);
  if (a == b) return 0.0;  // not turning: exactly 0 (the rotation between them would be rounding's 1e-8)
  // The rotation between the two, as 2 atan2(|vector part|, |scalar part|) (accurate for small angles too).
  const glm::dquat d = glm::conjugate(a) * b;
  return 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)) / dt;
}

double facing_turn_rate_rad_s(const WalkPath& walk, double t, double dt, double start) {
  const double since = std::min(dt, t - start);
  return since > 0 ? turn_rate_rad_s([&walk](double s) { return walk.facing(s); }, t, since) : 0.0;
}

glm::dvec3 eye_position(const glm::dvec3& head, const glm::dquat& q, int eye, int eyes, double ipd) {
  if (eyes < 2) return head;
  return head + (q * glm::dvec3(1, 0, 0)) * ((eye == 0 ? -0.5 : 0.5) * ipd);
}

WalkPath load_walk_file(const std::string& path) {
  return walk_from_json(parse_strict_json(read_input_file(path, 16 << 20, "walk file"), path), path);
}

WalkPath walk_from_json(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw InputError(path, "", "must be an object with speed and points");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "speed" && it.key() != "points") throw InputError(path, it.key(), "unknown key");
  const double speed = j.contains("speed") && j["speed"].is_number() ? j["speed"].get<double>() : (j.contains("speed") ? -1.0 : 1.0);
  std::vector<glm::dvec3> pts;
  if (!j.contains("points") || !j["points"].is_array()) throw InputError(path, "points", "must be an array of [x, y, z]");
  for (size_t i = 0; i < j["points"].size(); ++i) {
    const auto& p = j["points"][i];
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
      throw InputError(path, "points[" + std::to_string(i) + "]", "must be [x, y, z]");
    pts.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
  }
  return WalkPath(std::move(pts), speed, path);
}

int64_t walk_hash(const WalkPath& w) {
  Fingerprint h;
  h.add(static_cast<uint64_t>(w.points().size())).add(w.speed());
  for (const glm::dvec3& p : w.points()) h.add(p.x).add(p.y).add(p.z);
  return h.key();
}

}  // namespace arp::host
