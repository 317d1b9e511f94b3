#include "HostSimulation.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "host/render/FaceFootprint.hpp"

namespace arp::host {

HostSimulation::HostSimulation(const Scene& scene, const PriorityConfig& pc, const RenderEngine& engine, WalkPath walk,
                               std::function<glm::dquat(double)> head, dp::DisplayMemorySet& mem, double ipd,
                               double display_hz)
    : scene_(scene),
      sched_(scene, pc, mem.format().face_size),
      engine_(engine),
      walk_(std::move(walk)),
      head_(std::move(head)),
      mem_(mem),
      ipd_(ipd),
      display_hz_(display_hz),
      baseline_(pc.baseline),
      load_(static_cast<size_t>(mem.count())),
      pending_(static_cast<size_t>(mem.count())),
      from_(static_cast<size_t>(mem.count() * 2), glm::dvec3(std::numeric_limits<double>::quiet_NaN())),
      pending_from_(from_.size()),
      rendered_at_(static_cast<size_t>(mem.count()), std::numeric_limits<double>::quiet_NaN()),
      pending_at_(rendered_at_.size()),
      front_ids_(from_.size(), std::vector<FaceImage>(6)),
      pending_ids_(from_.size(), std::vector<FaceImage>(6)),
      shown_objects_(static_cast<size_t>(mem.count())),
      pending_objects_(static_cast<size_t>(mem.count())),
      shown_memory_(scene.objects.size(), -1) {
  // Memories holding only some tiles (memory.tiles): an object goes to a slower memory only where that memory
  // holds the tiles it covers (a standing user's objects would all go to the slowest memory, which a plan for
  // a walk sized for the far ones only) -- from eyes within half the eyes' distance of the walk's point, grown
  // by how far the eye and the object's own animation move before the engine starts the render (the planner's
  // bound is grown by a sample step, so a walk run as planned with no backlog is never held back).
  bool sparse = false, pooled = false;
  for (int m = 0; m < mem.count(); ++m) {
    sparse |= !mem.bank(0, m).holds_every_tile();
    pooled |= mem.bank(0, m).pool_slots() > 0;
  }
  if (!sparse && !pooled) return;
  for (const SceneObject& o : scene.objects) boxes_.push_back(mesh_box(*o.mesh));
  near_m_ = renderer_.depth().near_m;
  if (!sparse) return;
  sched_.set_fits([this](size_t i, int m, const glm::dvec3& eye, double t) {
    const dp::DisplayMemoryBank& bank = mem_.bank(0, m);  // every eye's bank of a memory holds the same tiles
    return bank.holds_every_tile() || each_object_tile(i, m, eye, t, [&](int f, int tx, int ty) { return bank.holds(f, tx, ty); });
  });
}

bool HostSimulation::each_object_tile(size_t i, int m, const glm::dvec3& eye, double t,
                                      const std::function<bool(int, int, int)>& visit) const {
  const dp::DisplayMemoryBank& bank = mem_.bank(0, m);
  const int S = bank.format().face_size;
  const double lag = std::max(0.0, engine_free_ - t);  // a render starts at max(t, engine free)
  const double margin = 0.5 * ipd_ + walk_.speed() * lag + animation_reach_m(scene_.objects[i], t, lag);
  for (int f = 0; f < 6; ++f) {
    if (!bank.format().present[static_cast<size_t>(f)]) continue;  // lost there whatever the memory
    const TexelRect r = object_face_rect(scene_.objects[i], boxes_[i], t, eye, margin, f, S, near_m_);
    if (!each_tile(r, [&](int tx, int ty) { return visit(f, tx, ty); })) return false;
  }
  return true;
}

void HostSimulation::keep_within_pools(const std::vector<char>& render, std::vector<int>& target, const glm::dvec3& eye, double t,
                                       bool first) {
  for (int m = mem_.count() - 1; m >= 0; --m) {
    const dp::DisplayMemoryBank& bank = mem_.bank(0, m);
    const int64_t slots = bank.pool_slots();
    if (!render[static_cast<size_t>(m)] || slots == 0) continue;
    // The image shown stays in its slots while the new one is drawn (the back buffer is cleared first).
    int64_t room = slots;
    for (int e = 0; e < mem_.eyes(); ++e) room = std::min(room, slots - mem_.bank(e, m).front_own_tiles());
    const int tpr = bank.tiles_per_row();
    std::vector<uint8_t> taken(static_cast<size_t>(6 * tpr * tpr), 0);
    std::vector<size_t> fresh;
    // The objects already in the memory first, then those joining it: a newcomer is taken only where both buffers
    // could hold its tiles, so that it still fits at the memory's next render, when this image is the one shown
    // (without that, a pool too small for two images of everything the rule puts there hands the same objects to
    // a faster memory and back, render after render). At the first render every object is a newcomer.
    for (const bool joining : {false, true})
      for (size_t i = 0; i < target.size(); ++i) {
        if (target[i] != m || (first || sched_.memory_of(i) != m) != joining) continue;
        fresh.clear();
        each_object_tile(i, m, eye, t, [&](int f, int tx, int ty) {
          const size_t k = static_cast<size_t>((f * tpr + ty) * tpr + tx);
          if (!taken[k] && bank.holds(f, tx, ty)) fresh.push_back(k);  // (a tile not held takes no slot: lost anyway)
          return true;
        });
        const int64_t n = static_cast<int64_t>(fresh.size());
        if ((joining ? 2 * n : n) > room)
          for (int k = m - 1; k >= 0; --k)
            if (render[static_cast<size_t>(k)] && sched_.fits(i, k, eye, t)) {
              target[i] = k;  // counted again where it lands (a faster memory comes later in this loop)
              break;
            }
        if (target[i] != m) continue;
        for (const size_t k : fresh) taken[k] = 1;  // drawn here (it fits, or has nowhere faster: what has no slot lost)
        room = std::max<int64_t>(0, room - n);
      }
  }
}

void HostSimulation::use_regions(RegionScheduler* regions, std::vector<int> object_region,
                                 std::vector<std::pair<RegionIndex, RegionIndex>> span) {
  regions_ = regions;
  sched_.set_fits({});  // regions place objects by region, not by the object rule: the tiles are not kept to there
  object_region_ = std::move(object_region);
  span_ = std::move(span);
}

int HostSimulation::memory_of_object(size_t i) const {
  return regions_->memory_of_object(object_region_[i], span_.empty() ? nullptr : &span_[i]);
}

std::vector<size_t> HostSimulation::objects_for(int m) const {
  if (!regions_) return sched_.objects_in(m);
  std::vector<size_t> out;
  for (size_t i = 0; i < object_region_.size(); ++i)
    if (memory_of_object(i) == m) out.push_back(i);
  return out;
}

EyeTurn HostSimulation::eye_turn_at(double t) const {
  if (mem_.eyes() < 2) return {};
  const double dt = 1.0 / display_hz_;
  return eye_turn(turn_rate_ ? turn_rate_(t, dt) : turn_rate_rad_s(head_, t, dt), ipd_);
}

void HostSimulation::prime(double t) {
  sched_.assign(walk_.position(t), walk_.speed(), eye_turn_at(t), t);
  sched_.settle();
  if (!regions_ && !boxes_.empty()) {  // every memory renders now: the pools as at any frame
    std::vector<int> target(scene_.objects.size());
    for (size_t i = 0; i < target.size(); ++i) target[i] = sched_.memory_of(i);
    keep_within_pools(std::vector<char>(static_cast<size_t>(mem_.count()), 1), target, walk_.position(t), t, true);
    for (size_t i = 0; i < target.size(); ++i) sched_.place(i, target[i]);
  }
  for (int m = 0; m < mem_.count(); ++m) {
    if (regions_) regions_->rendered(m, walk_.position(t));
    const std::vector<size_t> objs = objects_for(m);
    for (int e = 0; e < mem_.eyes(); ++e) {
      const glm::dvec3 eye = eye_position(walk_.position(t), head_(t), e, mem_.eyes(), ipd_);
      dp::DisplayMemoryBank& bank = mem_.bank(e, m);
      auto& ids = front_ids_[static_cast<size_t>(m * 2 + e)];
      if (objs.empty()) {
        bank.clear_back();
        bank.commit();
        for (auto& f : ids) f.object.clear();
      } else {
        bank_renderer_ ? bank_renderer_(scene_, objs, t, eye, bank, &ids) : renderer_.render(scene_, objs, t, eye, bank, &ids);
      }
      bank.vblank();
      from_[static_cast<size_t>(m * 2 + e)] = eye;
    }
    rendered_at_[static_cast<size_t>(m)] = t;
    shown_objects_[static_cast<size_t>(m)] = objs;
    for (size_t i : objs) shown_memory_[i] = m;
  }
}

void HostSimulation::before_frame(int64_t f, double t) {
  // Images whose render finished before this vertical blank swap in now.
  for (int m = 0; m < mem_.count(); ++m) {
    PendingImage& p = pending_[static_cast<size_t>(m)];
    if (p.swap_frame < 0 || p.swap_frame > f) continue;
    for (int e = 0; e < mem_.eyes(); ++e) mem_.bank(e, m).vblank();
    for (int e = 0; e < 2; ++e) {
      from_[static_cast<size_t>(m * 2 + e)] = pending_from_[static_cast<size_t>(m * 2 + e)];
      std::swap(front_ids_[static_cast<size_t>(m * 2 + e)], pending_ids_[static_cast<size_t>(m * 2 + e)]);
    }
    rendered_at_[static_cast<size_t>(m)] = pending_at_[static_cast<size_t>(m)];
    shown_objects_[static_cast<size_t>(m)] = pending_objects_[static_cast<size_t>(m)];
    for (size_t i : shown_objects_[static_cast<size_t>(m)]) shown_memory_[i] = m;
    p.swap_frame = -1;
  }
  const glm::dvec3 head_pos = walk_.position(t);
  sched_.assign(head_pos, walk_.speed(), eye_turn_at(t), t);
  for (size_t i = 0; i < scene_.objects.size() && !regions_; ++i) held_back_ += sched_.belongs_in(i) < sched_.rule_choice(i) ? 1 : 0;
  const int N = mem_.count();
  std::vector<char> render(static_cast<size_t>(N), 0), free(static_cast<size_t>(N), 0), moved(static_cast<size_t>(N), 0);
  bool all_free = true;
  for (int m = 0; m < N; ++m) {
    free[static_cast<size_t>(m)] = pending_[static_cast<size_t>(m)].swap_frame < 0;
    all_free = all_free && free[static_cast<size_t>(m)];
  }
  if (regions_) {
    // Regions: memories update on need; a re-assignment moves whole regions, all together.
    const RegionScheduler::Step st = regions_->step(head_pos, all_free);
    for (int m : st.update) {
      if (!free[static_cast<size_t>(m)]) {
        ++load_[static_cast<size_t>(m)].skipped;
        continue;
      }
      render[static_cast<size_t>(m)] = 1;
      moved[static_cast<size_t>(m)] = st.reassigned;
    }
  }
  for (int m = 0; m < N && !regions_; ++m) {
    const bool due = f % sched_.frames_per_update(m) == 0 && !(baseline_ && m > 0);
    if (due && !free[static_cast<size_t>(m)]) ++load_[static_cast<size_t>(m)].skipped;  // its last image is not even on screen yet
    render[static_cast<size_t>(m)] = due && free[static_cast<size_t>(m)];
  }
  // An object changes memory only when both memories render now: the one it
  // leaves and the one it joins re-render in the same frame and swap
  // together, so it is never on screen twice, nor missing. It waits for a
  // frame where its memory is due anyway rather than forcing a render (the
  // ladder's periods nest: a memory due now has every faster one due too),
  // and goes as far toward where it belongs as the memories due now allow.
  // Waiting never leaves theta_t: an object was placed, when its memory last
  // rendered, where its validity from then covers that memory's period, and
  // validity is direction-free (Validity.hpp), so the image stays within
  // theta_t until the memory's next scheduled render re-places it (tested).
  std::vector<int> moves_to(regions_ ? 0 : scene_.objects.size());  // each object's memory after this frame's moves
  for (size_t i = 0; i < moves_to.size(); ++i) {
    const int from = sched_.memory_of(i);
    moves_to[i] = from;
    if (!render[static_cast<size_t>(from)]) continue;
    int target = sched_.belongs_in(i);
    while (target != from && !render[static_cast<size_t>(target)]) target += target > from ? -1 : 1;
    // Where memories hold only some tiles, it is drawn only into one holding its tiles: a part-way move, a
    // memory it has outgrown, or one left rendering alone by an overload may not -- then the slowest memory
    // rendering now, faster than that, that does (none: stays, its texels there lost).
    if (!sched_.fits(i, target, head_pos, t))
      for (int k = target - 1; k >= 0; --k)
        if (render[static_cast<size_t>(k)] && sched_.fits(i, k, head_pos, t)) {
          target = k;
          break;
        }
    moves_to[i] = target;
  }
  if (!moves_to.empty() && !boxes_.empty()) {
    const std::vector<int> rule = moves_to;
    keep_within_pools(render, moves_to, head_pos, t, false);
    for (size_t i = 0; i < moves_to.size(); ++i) kept_for_pool_ += moves_to[i] < rule[i] ? 1 : 0;
  }
  for (size_t i = 0; i < moves_to.size(); ++i) {
    const int from = sched_.memory_of(i);
    if (moves_to[i] == from) continue;
    sched_.move_to(i, moves_to[i]);
    moved[static_cast<size_t>(from)] = moved[static_cast<size_t>(moves_to[i])] = 1;
  }
  int64_t handover_swap = -1;
  for (int m = 0; m < N; ++m) {
    if (!render[static_cast<size_t>(m)]) continue;
    MemoryLoad& L = load_[static_cast<size_t>(m)];
    PendingImage& p = pending_[static_cast<size_t>(m)];
    // The engine renders memories one after another, lowest (fastest) first.
    const double start = std::max(t, engine_free_);
    const std::vector<size_t> objs = objects_for(m);
    if (regions_) regions_->rendered(m, walk_.position(start));
    RenderStats sum;
    for (int e = 0; e < mem_.eyes(); ++e) {
      const glm::dvec3 eye = eye_position(walk_.position(start), head_(start), e, mem_.eyes(), ipd_);
      RenderStats st;
      auto& ids = pending_ids_[static_cast<size_t>(m * 2 + e)];
      if (objs.empty()) {
        mem_.bank(e, m).clear_back();  // nothing assigned: the memory shows nothing
        mem_.bank(e, m).commit();
        for (auto& face : ids) face.object.clear();
      } else if (regions_ && warp_) {
        const RegionGrid& g = regions_->grid();
        const glm::dvec3 now = walk_.position(start);
        const VertexWarp warp = [&, m, now, eye](size_t i, const glm::dvec3& w) {
          const RegionIndex r = g.unflat(object_region_[i]);
          double best = 0;
          glm::dvec3 shift(0.0);
          const double x0 = g.boundary_x(r.x), z0 = g.boundary_z(r.z), sz = g.size();
          const std::pair<RegionIndex, double> sides[4] = {{{r.x - 1, r.y, r.z}, w.x - x0}, {{r.x + 1, r.y, r.z}, x0 + sz - w.x},
                                                           {{r.x, r.y, r.z - 1}, w.z - z0}, {{r.x, r.y, r.z + 1}, z0 + sz - w.z}};
          for (const auto& [nb, dist] : sides) {
            if (nb.x < 0 || nb.z < 0 || nb.x >= g.count_x() || nb.z >= g.count_z()) continue;
            const int mn = regions_->memory_of_region(g.flat(nb));
            if (mn <= m || render[static_cast<size_t>(mn)]) continue;  // toward slower memories not re-rendered now
            const double wgt = std::max(0.0, 1.0 - std::max(0.0, dist) / falloff_);
            if (wgt > best) {
              best = wgt;
              shift = wgt * (now - regions_->last_rendered(mn));
            }
          }
          const double d = glm::length(w - eye);
          if (d > 0) max_warp_rad_ = std::max(max_warp_rad_, glm::length(shift) / d);
          return w + shift;
        };
        st = renderer_.render(scene_, objs, start, eye, mem_.bank(e, m), &ids, &warp);
      } else {
        st = bank_renderer_ ? bank_renderer_(scene_, objs, start, eye, mem_.bank(e, m), &ids)
                            : renderer_.render(scene_, objs, start, eye, mem_.bank(e, m), &ids);
      }
      sum.objects += st.objects;
      sum.triangles += st.triangles;
      sum.texels_filled += st.texels_filled;
      pending_from_[static_cast<size_t>(m * 2 + e)] = eye;
    }
    pending_at_[static_cast<size_t>(m)] = start;
    pending_objects_[static_cast<size_t>(m)] = objs;
    const double cost = engine_.seconds(sum);
    engine_free_ = start + cost;
    // The first vertical blank strictly after the render is done.
    p.done_s = engine_free_;
    p.swap_frame = static_cast<int64_t>(std::floor(engine_free_ * display_hz_ + 1e-9)) + 1;
    if (p.swap_frame <= f) p.swap_frame = f + 1;
    if (moved[static_cast<size_t>(m)]) handover_swap = std::max(handover_swap, p.swap_frame);
    ++L.updates;
    L.objects += sum.objects;
    L.triangles += sum.triangles;
    L.texels += sum.texels_filled;
    L.busy_s += cost;
  }
  // Memories exchanging objects swap at the same blank: the last of them to finish.
  for (int m = 0; m < N; ++m)
    if (moved[static_cast<size_t>(m)]) pending_[static_cast<size_t>(m)].swap_frame = handover_swap;
}

int64_t HostSimulation::full_render_triangles(double t) const {
  int64_t n = 0;
  for (int e = 0; e < mem_.eyes(); ++e)
    n += renderer_.count(scene_, {}, t, eye_position(walk_.position(t), head_(t), e, mem_.eyes(), ipd_)).triangles;
  return n;
}

}  // namespace arp::host
