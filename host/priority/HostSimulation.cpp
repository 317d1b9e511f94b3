#include "HostSimulation.hpp"

#include <cmath>
#include <limits>

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
      pending_ids_(from_.size(), std::vector<FaceImage>(6)) {}

void HostSimulation::prime(double t) {
  sched_.assign(walk_.position(t), walk_.speed(), t);
  for (int m = 0; m < mem_.count(); ++m) {
    const std::vector<size_t> objs = sched_.objects_in(m);
    for (int e = 0; e < mem_.eyes(); ++e) {
      const glm::dvec3 eye = eye_position(walk_.position(t), head_(t), e, mem_.eyes(), ipd_);
      dp::DisplayMemoryBank& bank = mem_.bank(e, m);
      auto& ids = front_ids_[static_cast<size_t>(m * 2 + e)];
      if (objs.empty()) {
        bank.clear_back();
        bank.commit();
        for (auto& f : ids) f.object.clear();
      } else {
        renderer_.render(scene_, objs, t, eye, bank, &ids);
      }
      bank.vblank();
      from_[static_cast<size_t>(m * 2 + e)] = eye;
    }
    rendered_at_[static_cast<size_t>(m)] = t;
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
    p.swap_frame = -1;
  }
  const glm::dvec3 head_pos = walk_.position(t);
  const glm::dquat q = head_(t);
  sched_.assign(head_pos, walk_.speed(), t);
  for (int m = 0; m < mem_.count(); ++m) {
    if (f % sched_.frames_per_update(m) != 0) continue;
    if (baseline_ && m > 0) continue;  // the baseline uses memory 0 only
    MemoryLoad& L = load_[static_cast<size_t>(m)];
    PendingImage& p = pending_[static_cast<size_t>(m)];
    if (p.swap_frame >= 0) {  // its last image is not even on screen yet
      ++L.skipped;
      continue;
    }
    // The engine renders memories one after another, lowest (fastest) first.
    const double start = std::max(t, engine_free_);
    const std::vector<size_t> objs = sched_.objects_in(m);
    RenderStats sum;
    for (int e = 0; e < mem_.eyes(); ++e) {
      const glm::dvec3 eye = eye_position(walk_.position(start), head_(start), e, mem_.eyes(), ipd_);
      RenderStats st;
      auto& ids = pending_ids_[static_cast<size_t>(m * 2 + e)];
      if (objs.empty()) {
        mem_.bank(e, m).clear_back();  // nothing assigned: the memory shows nothing
        mem_.bank(e, m).commit();
        for (auto& face : ids) face.object.clear();
      } else {
        st = renderer_.render(scene_, objs, start, eye, mem_.bank(e, m), &ids);
      }
      sum.objects += st.objects;
      sum.triangles += st.triangles;
      sum.texels_filled += st.texels_filled;
      pending_from_[static_cast<size_t>(m * 2 + e)] = eye;
    }
    pending_at_[static_cast<size_t>(m)] = start;
    const double cost = engine_.seconds(sum);
    engine_free_ = start + cost;
    // The first vertical blank strictly after the render is done.
    p.done_s = engine_free_;
    p.swap_frame = static_cast<int64_t>(std::floor(engine_free_ * display_hz_ + 1e-9)) + 1;
    if (p.swap_frame <= f) p.swap_frame = f + 1;
    ++L.updates;
    L.objects += sum.objects;
    L.triangles += sum.triangles;
    L.texels += sum.texels_filled;
    L.busy_s += cost;
  }
  (void)q;
}

int64_t HostSimulation::full_render_triangles(double t) const {
  int64_t n = 0;
  for (int e = 0; e < mem_.eyes(); ++e)
    n += renderer_.count(scene_, {}, t, eye_position(walk_.position(t), head_(t), e, mem_.eyes(), ipd_)).triangles;
  return n;
}

}  // namespace arp::host
