// The host over time: a user walking through a scene, the priority
// scheduler sorting objects into memories, one simulated rendering engine
// rendering each memory when it is due (both eyes, from the eye positions at
// the render's start), and the new images swapped in at the first vertical
// blank after the render finishes. When a memory is due while its previous
// render has not been swapped in yet, the update is skipped (overload): the
// old image stays, still rotated correctly by the pipeline.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "PriorityScheduler.hpp"
#include "RenderCost.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::host {

struct MemoryLoad {
  int64_t updates = 0, skipped = 0;    // renders done, renders skipped for overload
  int64_t objects = 0, triangles = 0, texels = 0;  // summed over updates (both eyes)
  double busy_s = 0;                   // simulated render time
};

struct PendingImage {
  int64_t swap_frame = -1;             // -1: nothing pending
  double done_s = 0;
};

class HostSimulation {
 public:
  // `head(t)`: the head orientation at time t (for the eye positions).
  HostSimulation(const Scene& scene, const PriorityConfig& pc, const RenderEngine& engine, WalkPath walk,
                 std::function<glm::dquat(double)> head, dp::DisplayMemorySet& mem, double ipd_m,
                 double display_hz);
  HostSimulation(const HostSimulation&) = delete;  // the scheduler's tile test refers to this object
  HostSimulation& operator=(const HostSimulation&) = delete;

  // Draws objects into a bank as CubeFaceRenderer::render does (no vertex warp): how another
  // renderer (OpenGL, sim/Session) replaces the software one. Region warping needs the software one.
  using BankRenderer = std::function<RenderStats(const Scene&, const std::vector<size_t>&, double, const glm::dvec3&,
                                                 dp::DisplayMemoryBank&, std::vector<FaceImage>*)>;
  void use_renderer(BankRenderer r) { bank_renderer_ = std::move(r); }
  // The head's mean turn rate over [t - dt, t], rad/s, where it is known better than from head(t) at two
  // times (a head that only faces the walk: facing_turn_rate_rad_s, as its plan takes it). Unset: from head.
  using TurnRate = std::function<double(double t_s, double dt_s)>;
  void use_turn_rate(TurnRate f) { turn_rate_ = std::move(f); }
  // Threads the software renderer draws faces on (0: every core): the run's --threads.
  void set_render_threads(int n) { renderer_.set_threads(n); }
  // The software renderer's per-face culling (off: every object on every face; the modelled load counts what is drawn).
  void set_face_culling(bool on) { renderer_.set_face_culling(on); }

  // Region priority rendering instead of object-level: each object of the
  // (segmented) scene belongs to `object_region[i]`, whose memory the region
  // scheduler decides; memories update on need; a re-assignment re-renders
  // every memory it changes and swaps them together.
  // `span`: optional, per object the box of regions its bound reaches; the
  // object then goes to the fastest memory among them.
  void use_regions(RegionScheduler* regions, std::vector<int> object_region,
                   std::vector<std::pair<RegionIndex, RegionIndex>> span = {});
  // Region warping (Chow 2005): when a memory renders, vertices near the edge
  // of its regions toward a slower neighbouring memory's region move by the
  // user's position now minus where that slower memory was rendered -- fully
  // on the edge, falling off linearly to nothing at `falloff_m` inside.
  void use_warping(bool on, double falloff_m) {
    warp_ = on;
    falloff_ = falloff_m;
  }
  // The largest vertex displacement warping has caused, in radians as seen from the eye.
  double max_warp_rad() const { return max_warp_rad_; }

  // The state before the run: every memory rendered at t_s and on screen
  // (a scene already loaded; not counted as load).
  void prime(double t_s);
  // The vertical blank before frame f, at time t_s: swaps finished images in,
  // then starts the renders due at this frame.
  void before_frame(int64_t f, double t_s);

  const std::vector<MemoryLoad>& load() const { return load_; }
  const PriorityScheduler& scheduler() const { return sched_; }
  double engine_busy_until() const { return engine_free_; }
  // Object-frames whose destination was a faster memory than the rule's, for its tiles (memory.tiles).
  int64_t held_back() const { return held_back_; }
  // Object-frames sent to (or kept in) a faster memory rendering at the same frame than the one the rule's move
  // would have drawn them in, because that memory's tile pool (memory.tile_pool) had no room for their tiles.
  int64_t kept_for_pool() const { return kept_for_pool_; }
  // Triangles a full render of the whole scene would set up now (both eyes): the baseline's load per frame.
  int64_t full_render_triangles(double t_s) const;
  // Where the eye was when memory m's displayed image was rendered (NaN before the first).
  glm::dvec3 rendered_from(int m, int eye) const { return from_[static_cast<size_t>(m * 2 + eye)]; }
  // The visible object (scene index + 1, 0: none) of texel (x, y) of `face` in memory m's image on screen.
  uint32_t shown_object(int m, int eye, int face, int x, int y) const {
    const FaceImage& f = front_ids_[static_cast<size_t>(m * 2 + eye)][static_cast<size_t>(face)];
    return f.object.empty() ? 0u : f.object[static_cast<size_t>(y) * static_cast<size_t>(f.size) + static_cast<size_t>(x)];
  }
  double rendered_at(int m) const { return rendered_at_[static_cast<size_t>(m)]; }
  // The objects memory m's image on screen was rendered with.
  const std::vector<size_t>& shown_objects(int m) const { return shown_objects_[static_cast<size_t>(m)]; }
  // The objects in memory m now, by the object rule or, with regions, by their regions' memory (scene order).
  std::vector<size_t> objects_for(int m) const;
  // The memory whose image on screen shows object i (-1 before the first render).
  int shown_in(size_t object) const { return shown_memory_[object]; }

 private:
  // The eyes' motion from the head's mean turn rate over the frame before t (one eye: none), for the rule.
  EyeTurn eye_turn_at(double t_s) const;

  const Scene& scene_;
  PriorityScheduler sched_;
  RenderEngine engine_;
  WalkPath walk_;
  std::function<glm::dquat(double)> head_;
  TurnRate turn_rate_;
  dp::DisplayMemorySet& mem_;
  double ipd_, display_hz_;
  bool baseline_;
  CubeFaceRenderer renderer_;
  BankRenderer bank_renderer_;  // empty: renderer_
  std::vector<MemoryLoad> load_;
  std::vector<PendingImage> pending_;
  std::vector<glm::dvec3> from_, pending_from_;
  std::vector<double> rendered_at_, pending_at_;
  std::vector<std::vector<FaceImage>> front_ids_, pending_ids_;  // per memory and eye: visible objects
  std::vector<std::vector<size_t>> shown_objects_, pending_objects_;  // per memory: the objects its image holds
  std::vector<int> shown_memory_;  // per object
  RegionScheduler* regions_ = nullptr;
  bool warp_ = false;
  double falloff_ = 1.0, max_warp_rad_ = 0;
  std::vector<int> object_region_;
  std::vector<std::pair<RegionIndex, RegionIndex>> span_;
  int memory_of_object(size_t i) const;
  // Calls visit(face, tx, ty) for the tiles of memory m's faces present object i can be drawn on for a render
  // asked for at t (its rectangle from eyes within half the eyes' distance of `eye`, grown by how far the eye
  // and its own animation move before the engine starts); false as soon as visit returns false.
  bool each_object_tile(size_t i, int m, const glm::dvec3& eye, double t, const std::function<bool(int, int, int)>& visit) const;
  // Memories with a tile pool rendering now, slowest first: an object whose tiles would overfill the pool (with
  // the image shown) goes to the slowest faster memory rendering now that holds its tiles (none: it stays).
  // `target`: each object's memory after this frame's moves, changed here; `first`: the run's first render.
  void keep_within_pools(const std::vector<char>& render, std::vector<int>& target, const glm::dvec3& eye, double t, bool first);
  std::vector<std::array<glm::dvec3, 2>> boxes_;  // each object's mesh box, where memories hold some tiles or pools
  double near_m_ = 0;
  double engine_free_ = -1e300;
  int64_t held_back_ = 0, kept_for_pool_ = 0;
};

}  // namespace arp::host
