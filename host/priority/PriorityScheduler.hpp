// Object-level priority rendering (Regan & Pose): N display memories updated
// at rates dividing the display's (60, 30, 15, 7.5 Hz by default; memory.update_*); each
// object belongs in the slowest memory whose update period is within its
// validity period (memory 0 if none is), so objects whose image stays right
// longer are rendered less often. assign() works out where each object
// belongs; an object actually moves (move(), move_to()) when the host
// re-renders both memories together, so it is never shown by two memories,
// nor by none (HostSimulation decides when; tested). The baseline renders
// everything into memory 0 every frame. Where memories hold only some tiles
// (memory.tiles), an object goes no slower than the slowest memory at or
// below its rule's choice that holds the tiles it draws on (set_fits). Objects named in memory.assignment
// are kept within their memories: the rule's choice is clamped to them (before the tiles' choice).
#pragma once
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "Validity.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "host/scene/Scene.hpp"

namespace arp::host {

struct PriorityConfig {
  int memories = 4;
  int update_frames = 1, update_ratio = 2;  // memory m: every update_frames x update_ratio^m frames (memory.update_*)
  double display_hz = 60.0;
  double threshold_rad = 0.0;   // 0: the angle of one display-memory texel at a face centre, (pi/2) / face_size
  bool baseline = false;        // everything in memory 0, rendered every frame
  std::vector<dp::ObjectAssignment> assignment;  // memory.assignment: the memories named objects are kept in

  // The memories and their update ladder as a configuration sets them (memory.count, memory.update_*,
  // memory.assignment; std::invalid_argument where the last does not parse: a configuration not validated).
  static PriorityConfig of(const dp::MemoryConfig& m, double display_hz) {
    PriorityConfig pc;
    std::string why;
    if (!dp::object_assignments(m, pc.assignment, why)) throw std::invalid_argument("memory.assignment: " + why);
    pc.memories = m.count;
    pc.update_frames = m.update_frames;
    pc.update_ratio = m.update_ratio;
    pc.threshold_rad = m.threshold_deg * (3.14159265358979323846 / 180.0);  // (common/Units' kPi would clash in includers)
    pc.display_hz = display_hz;
    return pc;
  }
};

// How long object o's image stays within threshold_rad for a user at `eye` moving at user_speed at time
// t, the eyes moving by `turn` besides (its own path speed and spin included): the rule assign() places
// objects by.
Validity object_validity(const SceneObject& o, const glm::dvec3& eye, double user_speed_m_s, const EyeTurn& turn, double t_s,
                         double threshold_rad);

// The names of `assignment` (memory.assignment's entries) no object of `scene` has, in the order given.
std::vector<std::string> unknown_assignment_names(const Scene& scene, const std::vector<dp::ObjectAssignment>& assignment);

class PriorityScheduler {
 public:
  PriorityScheduler(const Scene& scene, const PriorityConfig& cfg, int face_size);

  // Frames between updates of memory m: update_frames x update_ratio^m (1, 2, 4, 8, ... by default).
  int64_t frames_per_update(int m) const {
    return cfg_.baseline ? 1 : dp::update_period_frames(cfg_.update_frames, cfg_.update_ratio, m);
  }
  double period_s(int m) const { return static_cast<double>(frames_per_update(m)) / cfg_.display_hz; }
  double threshold_rad() const { return threshold_; }

  // Works out where every object belongs for the user at `eye` moving at `user_speed`, the eyes by `turn`, at time t.
  void assign(const glm::dvec3& eye, double user_speed_m_s, const EyeTurn& turn, double t_s);
  // Whether object `object` at time t, seen from eyes about `eye`, draws only on tiles memory m holds. With
  // one set, assign() puts an object in the slowest memory at or below the rule's choice that holds them
  // (the rule's choice when none of those does: its texels there are lost).
  using Fits = std::function<bool(size_t object, int memory, const glm::dvec3& eye, double t_s)>;
  void set_fits(Fits f) { fits_ = std::move(f); }
  bool fits(size_t object, int m, const glm::dvec3& eye, double t_s) const { return !fits_ || fits_(object, m, eye, t_s); }
  int rule_choice(size_t object) const { return rule_[object]; }  // where the rule puts it (assignment, not the tiles)
  // The memories memory.assignment keeps an object in (every memory where it names none of that name).
  int fastest_allowed(size_t object) const { return fastest_[object]; }
  int slowest_allowed(size_t object) const { return slowest_[object]; }
  // memory.assignment's names no object of the scene has, in the order given (unknown_assignment_names).
  const std::vector<std::string>& unknown_names() const { return unknown_; }
  // Object placements (assign() calls times objects) the assignment kept slower than the validity rule put
  // them (their images may move further than theta_t before the next update), and faster.
  int64_t held_slower() const { return held_slower_; }
  int64_t held_faster() const { return held_faster_; }
  int memory_of(size_t object) const { return memory_[object]; }    // where it is
  int belongs_in(size_t object) const { return desired_[object]; }  // where it should go
  void move(size_t object) { move_to(object, desired_[object]); }
  void move_to(size_t object, int m) {  // (toward where it belongs, as far as the memories rendering now allow)
    if (memory_[object] != m) ++moves_;
    memory_[object] = m;
  }
  void settle() {  // every object where it belongs (before a run)
    for (size_t i = 0; i < memory_.size(); ++i) memory_[i] = desired_[i];
  }
  void place(size_t object, int m) { memory_[object] = m; }  // where it is before a run (not a move)
  // The objects currently in memory m, in scene order.
  std::vector<size_t> objects_in(int m) const;
  int64_t moves() const { return moves_; }  // objects promoted or demoted so far

 private:
  const Scene& scene_;
  PriorityConfig cfg_;
  double threshold_;
  std::vector<int> memory_, desired_, rule_, fastest_, slowest_;
  std::vector<std::string> unknown_;
  int64_t moves_ = 0, held_slower_ = 0, held_faster_ = 0;
  Fits fits_;
};

}  // namespace arp::host
