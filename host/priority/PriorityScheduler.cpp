#include "PriorityScheduler.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include "common/Units.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"

namespace arp::host {

Validity object_validity(const SceneObject& o, const glm::dvec3& eye, double user_speed, const EyeTurn& turn, double t,
                         double threshold_rad) {
  const Sphere b = o.world_bound(t);
  const auto& a = o.animation;
  const double own_speed = (a.path.size() >= 2 && a.path_speed > 0) ? a.path_speed : 0.0;
  return validity({glm::length(b.center - eye), b.radius, user_speed + own_speed, std::abs(a.spin_deg_per_s) * kPi / 180.0},
                  threshold_rad, turn);
}

std::vector<std::string> unknown_assignment_names(const Scene& scene, const std::vector<dp::ObjectAssignment>& assignment) {
  std::vector<std::string> unknown;
  if (assignment.empty()) return unknown;
  std::set<std::string> names;
  for (const SceneObject& o : scene.objects) names.insert(o.name);
  for (const dp::ObjectAssignment& a : assignment)
    if (!names.count(a.name)) unknown.push_back(a.name);
  return unknown;
}

PriorityScheduler::PriorityScheduler(const Scene& scene, const PriorityConfig& cfg, int face_size)
    : scene_(scene),
      cfg_(cfg),
      threshold_(cfg.threshold_rad > 0 ? cfg.threshold_rad : dp::texel_angle_rad(face_size)),
      memory_(scene.objects.size(), 0),
      desired_(scene.objects.size(), 0),
      rule_(scene.objects.size(), 0),
      fastest_(scene.objects.size(), 0),
      slowest_(scene.objects.size(), std::max(0, cfg.memories - 1)),
      unknown_(unknown_assignment_names(scene, cfg.assignment)) {
  std::map<std::string, std::vector<size_t>> named;  // name -> its objects
  if (!cfg_.assignment.empty())
    for (size_t i = 0; i < scene.objects.size(); ++i) named[scene.objects[i].name].push_back(i);
  for (const dp::ObjectAssignment& a : cfg_.assignment) {
    const auto objects = named.find(a.name);
    if (objects == named.end()) continue;  // (unknown_)
    for (const size_t i : objects->second) {
      fastest_[i] = std::min(a.fastest, cfg_.memories - 1);
      slowest_[i] = std::min(a.slowest, cfg_.memories - 1);
    }
  }
}

void PriorityScheduler::assign(const glm::dvec3& eye, double user_speed, const EyeTurn& turn, double t) {
  for (size_t i = 0; i < scene_.objects.size(); ++i) {
    int m = 0;
    if (!cfg_.baseline) {
      const double p = object_validity(scene_.objects[i], eye, user_speed, turn, t, threshold_).period_s();
      while (m + 1 < cfg_.memories && period_s(m + 1) <= p) ++m;
      held_slower_ += m < fastest_[i] ? 1 : 0;
      held_faster_ += m > slowest_[i] ? 1 : 0;
      m = std::clamp(m, fastest_[i], slowest_[i]);
    }
    rule_[i] = m;
    if (fits_ && m > 0) {
      int k = m;
      while (k > 0 && !fits_(i, k, eye, t)) --k;
      // k < m: memory k holds its tiles, or k = 0 -- taken only if memory 0 holds them (else none at or below does).
      if (k < m && (k > 0 || fits_(i, 0, eye, t))) m = k;
    }
    desired_[i] = m;
  }
}

std::vector<size_t> PriorityScheduler::objects_in(int m) const {
  std::vector<size_t> out;
  for (size_t i = 0; i < memory_.size(); ++i)
    if (memory_[i] == m) out.push_back(i);
  return out;
}

}  // namespace arp::host
