#include "Planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "CompositionDepth.hpp"
#include "ConfigFile.hpp"
#include "HardwareCost.hpp"
#include "HeadMotion.hpp"
#include "MemoryContents.hpp"
#include "TradeMeasure.hpp"
#include "common/PrintfText.hpp"
#include "common/InputError.hpp"
#include "common/Units.hpp"
#include "host/priority/PriorityScheduler.hpp"
#include "host/priority/RenderCost.hpp"
#include "host/priority/Validity.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "host/regions/Segmentation.hpp"
#include "host/render/CubeFaceRenderer.hpp"
#include "host/render/DepthCode.hpp"
#include "host/render/FaceFootprint.hpp"
#include "host/render/FaceFrustum.hpp"
#include "host/scene/Gallery.hpp"
#include "reference/accuracy/AccuracyHarness.hpp"
#include "reference/golden/GoldenReference.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::sim {

namespace {

// The plan's steps in the order make_plan takes them, for its progress (PlanRequest::progress).
enum PlanStep : int {
  kStepScene = 1,
  kStepPixelAngles,
  kStepWidths,
  kStepFill,
  kStepLadders,
  kStepLimitTiles,
  kStepBaseFill,
  kStepMemoryFill,
  kStepEngine,
  kStepPlannedTiles,
  kStepDepthCode,
  kStepRegions,
  kPlanSteps = kStepRegions
};

// The longest motion a plan covers: region priority rendering is weighed by stepping the region rule at every
// display frame, and frame times are whole picoseconds (a walk at a vanishing speed would last for ever).
constexpr double kMaxPlanSpanS = 3600.0;
constexpr int kCompositionPoints = 16;  // of them, where the depth code's composition is measured

// The smallest angle between neighbouring display pixels (across and down) after the lens, and the
// angle at the panel's centre, from the golden reference's exact lens directions (eye 0; the other
// eye mirrors it).
std::pair<double, double> pixel_angles(const dp::ArpConfig& c) {
  const int W = c.timing.h_active, H = c.timing.v_active;
  if (W < 2 || H < 2)
    throw InputError(W < 2 ? "display.h_active" : "display.v_active", std::to_string(W < 2 ? W : H),
                     "a plan sizes the faces from the angle between neighbouring display pixels: it needs a display of at "
                     "least 2 x 2 pixels");
  std::vector<glm::dvec3> d(static_cast<size_t>(W) * static_cast<size_t>(H));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) d[static_cast<size_t>(y) * static_cast<size_t>(W) + static_cast<size_t>(x)] = golden::lens_direction(c, 0, x, y);
  auto angle = [](const glm::dvec3& a, const glm::dvec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); };
  double lo = std::numeric_limits<double>::infinity();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const glm::dvec3& p = d[static_cast<size_t>(y) * static_cast<size_t>(W) + static_cast<size_t>(x)];
      if (x + 1 < W) lo = std::min(lo, angle(p, d[static_cast<size_t>(y) * static_cast<size_t>(W) + static_cast<size_t>(x + 1)]));
      if (y + 1 < H) lo = std::min(lo, angle(p, d[static_cast<size_t>(y + 1) * static_cast<size_t>(W) + static_cast<size_t>(x)]));
    }
  const int cx = W / 2, cy = H / 2;
  const double centre = W > 1 ? angle(d[static_cast<size_t>(cy) * static_cast<size_t>(W) + static_cast<size_t>(cx - 1)],
                                      d[static_cast<size_t>(cy) * static_cast<size_t>(W) + static_cast<size_t>(cx)])
                              : lo;
  return {lo, centre};
}

// The datapath widths the planner narrows, in the order it tries them (their ranges: the parameter table).
struct WidthKey {
  const char* key;
  int dp::DatapathWidths::*field;
  int lo() const { return static_cast<int>(dp::arp_parameters().find(key)->int_min); }
  int hi() const { return static_cast<int>(dp::arp_parameters().find(key)->int_max); }
};
constexpr WidthKey kWidths[] = {
    {"datapath.vec_frac", &dp::DatapathWidths::vec_frac},
    {"datapath.mat_frac", &dp::DatapathWidths::mat_frac},
    {"datapath.rot_frac", &dp::DatapathWidths::rot_frac},
    {"datapath.quot_frac", &dp::DatapathWidths::quot_frac},
    {"datapath.recip_frac_bits", &dp::DatapathWidths::recip_frac_bits},
    {"datapath.newton_steps", &dp::DatapathWidths::newton_steps},  // before the table: a step costs two multipliers
    {"datapath.recip_index_bits", &dp::DatapathWidths::recip_index_bits},
};

class WidthSearch {
 public:
  WidthSearch(const PlanRequest& r, Plan& p) : req_(r), plan_(p) {
    opt_ = accuracy_options(TradeScale{true});
    opt_.color_orientations = 0;  // the bound is on texel position; colour follows from it
    opt_.aligned = false;         // the aligned views are reported apart from the pooled error the bound is on
  }
  // The harness's largest texel-position error for c; +inf when c is not a valid configuration.
  double error(const dp::ArpConfig& c) {
    if (!dp::validate(c).empty()) return std::numeric_limits<double>::infinity();
    ++plan_.harness_runs;
    if (req_.progress)
      req_.progress(kStepWidths, kPlanSteps, std::min(0.99, static_cast<double>(plan_.harness_runs) / static_cast<double>(expected_)),
                    "datapath widths");
    return accuracy::run(c, opt_).overall.max_error;
  }
  // The harness runs the search is expected to take, for its progress.
  void expect(int runs) { expected_ = std::max(1, runs); }

 private:
  const PlanRequest& req_;
  Plan& plan_;
  accuracy::Options opt_;
  int expected_ = 40;
};

std::string face_list(const std::array<int, 6>& faces) {
  std::string s = "[";
  for (size_t f = 0; f < 6; ++f) s += (f ? ", " : "") + std::to_string(faces[f]);
  return s + "]";
}

std::string widths_text(const dp::DatapathWidths& w) {
  std::string s;
  for (const WidthKey& k : kWidths) s += (s.empty() ? "" : ", ") + std::string(k.key + 9) + " " + std::to_string(w.*k.field);
  return s;
}

// The motion planned over: the walk's points at display-frame times, at most kMaxSamples of them.
struct MotionSamples {
  std::vector<double> t;
  std::vector<host::EyeTurn> turn;  // at each: the eyes' turning, as the run's rule takes it (HeadTurnRate)
  double span_s = 0;
  double step_s = 0;  // between samples
};

// The motion planned over: the walk's points at display-frame times (walking, the walk's span; standing, the
// head motion's: standing_span_s), at most kMaxSamples of them, and at each the eyes' turning as a run's rule takes
// it (HostSimulation::eye_turn_at): the head's turn over the frame before, from the walk's facing and the head
// motion (HeadTurnRate), for eyes ipd_m apart (0: one eye, no turn).
// The walk's span (nullopt standing still: the head motion's is planned over, standing_span_s).
std::optional<double> walk_span_s(const host::WalkPath& walk) {
  return walk.speed() > 0 ? std::optional<double>(walk.length() / walk.speed()) : std::nullopt;
}

MotionSamples sample_motion(const host::WalkPath& walk, const HeadMotion& head, const dp::VideoTiming& vt, double ipd_m) {
  const double hz = vt.refresh_hz();
  MotionSamples m;
  const std::optional<double> walking = walk_span_s(walk);
  m.span_s = walking ? *walking : standing_span_s(head);
  if (!(m.span_s <= kMaxPlanSpanS)) {
    const std::string lasts = printf_text("%.6g s", m.span_s), limit = "a plan covers at most an hour (" +
                                                                       printf_text("%g", kMaxPlanSpanS) + " s) of motion";
    if (walking)
      throw InputError("--walk", "",
                       printf_text("%.6g m", walk.length()) + " at " + printf_text("%.6g m/s", walk.speed()) + " lasts " + lasts +
                           "; " + limit + ": plan a faster walk (--speed) or a part of it");
    throw InputError(head.trace.empty() ? "--motion" : "--trace", head.trace.empty() ? head.describe() : head.trace,
                     "standing, the plan covers the head motion's span, " + lasts + "; " + limit);
  }
  // (every sample within the motion: past its end a looping walk would be back at its start)
  const int64_t frames = static_cast<int64_t>(std::floor(m.span_s * hz) + 1);
  const int64_t step = std::max<int64_t>(1, (frames + kMaxSamples - 1) / kMaxSamples);
  HeadTurnRate rate(walk, head, m.span_s);
  for (int64_t f = 0; f < frames; f += step) {
    m.t.push_back(vt.frame_start_s(f));  // (as a run's host is told it: the frame's whole picosecond)
    m.turn.push_back(rate.eyes_at(m.t.back(), 1.0 / hz, ipd_m));
  }
  m.step_s = static_cast<double>(step) / hz;
  return m;
}

// The sample index of the j-th of `points` rendered points, evenly spread over `samples` (the first and the last
// included).
size_t rendered_sample(size_t j, size_t points, size_t samples) {
  return points == 1 ? 0 : (j * (samples - 1) + (points - 1) / 2) / (points - 1);
}

// Texels each object fills (passing the depth test) per update at each sample (k * objects + i), for one
// eye: the whole scene rendered from the walk's point at face size S, by the run's own renderer, at
// `fill_points` samples evenly spread over the motion; every other sample interpolates the two around it.
// Within one render an object's fill is at most what it fills in a memory holding only some of the objects
// (fewer occluders drawn before it: host::CubeFaceRenderer draws in scene order), so for any ladder each
// rendered point's figure is a lower bound; the samples between are not rendered, and their figures are
// an estimate, not a bound (an object that comes close between two rendered points is under-counted).

struct FillSamples {
  std::vector<double> texels;  // k * objects + i
  int points = 0;              // samples rendered
};
// With `belongs` (k * objects + i: the memory the rule puts object i in at sample k, as engine_need replays it), each
// rendered point draws each memory's objects on their own, as that memory's render in a run draws them: an object's
// fill is then what it fills among its own memory's objects (no more hidden behind a nearer object of another
// memory), not the lower bound the whole scene gives.
FillSamples measure_fill(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms, int S, int fill_points,
                         const std::function<void(double)>& progress, const std::vector<int>* belongs = nullptr) {
  const size_t n = scene.objects.size(), samples = ms.t.size();
  FillSamples out;
  out.texels.assign(samples * n, 0.0);
  if (n == 0 || samples == 0) return out;
  const size_t points = std::min<size_t>(samples, static_cast<size_t>(fill_points));
  host::CubeFaceRenderer renderer;
  renderer.set_fill_by_object(true);
  std::vector<host::FaceImage> faces;
  std::vector<std::vector<int64_t>> at(points);
  std::vector<size_t> sample_of(points);
  for (size_t j = 0; j < points; ++j) {
    const size_t k = sample_of[j] = rendered_sample(j, points, samples);
    if (!belongs) {
      at[j] = renderer.render_faces(scene, {}, ms.t[k], walk.position(ms.t[k]), S, faces).filled_by_object;
    } else {
      std::map<int, std::vector<size_t>> memories;  // memory -> its objects at this sample
      for (size_t i = 0; i < n; ++i) memories[(*belongs)[k * n + i]].push_back(i);
      at[j].assign(n, 0);
      for (const auto& [m, objects] : memories) {
        const std::vector<int64_t> f = renderer.render_faces(scene, objects, ms.t[k], walk.position(ms.t[k]), S, faces).filled_by_object;
        for (const size_t i : objects) at[j][i] = f[i];
      }
    }
    progress(static_cast<double>(j + 1) / static_cast<double>(points));
  }
  // Between two rendered points, each object's fill interpolated linearly in the sample index.
  size_t j = 0;
  for (size_t k = 0; k < samples; ++k) {
    while (j + 1 < points && sample_of[j + 1] <= k) ++j;
    const size_t j1 = std::min(j + 1, points - 1);
    const double f = sample_of[j1] > sample_of[j]
                         ? static_cast<double>(k - sample_of[j]) / static_cast<double>(sample_of[j1] - sample_of[j])
                         : 0.0;
    for (size_t i = 0; i < n; ++i)  // (whole texels, as a render counts them)
      out.texels[k * n + i] = std::round((1 - f) * static_cast<double>(at[j][i]) + f * static_cast<double>(at[j1][i]));
  }
  out.points = static_cast<int>(points);
  return out;
}

// What drawing object `o` at time t for one eye at `head` costs the engine (RenderStats): its set-up, its triangles
// once for every face its bound reaches -- by the renderers' culling test (host::sphere_meets_face, as
// host::cull_to_faces sends them) with the bound shrunk by half the distance between the eyes, what the shrunk
// sphere meets from `head` the whole one meets from either eye -- and one face at least, and `fill` texels.
host::RenderStats drawing(const host::SceneObject& o, double t, const glm::dvec3& head, double ipd_m, int64_t fill) {
  const double near_m = host::DepthCode{}.near_m, half_ipd = 0.5 * ipd_m;
  const host::Sphere b = o.world_bound(t);
  int faces = 0;
  for (int f = 0; f < 6; ++f) faces += host::sphere_meets_face(b.center - head, b.radius - half_ipd, f, near_m) ? 1 : 0;
  host::RenderStats drawn;
  drawn.objects = 1;
  drawn.triangles = static_cast<int64_t>(o.mesh->triangles()) * std::max(faces, 1);
  drawn.texels_filled = fill;
  return drawn;
}

// Engine seconds per update of each object at each sample (k * objects + i): drawing() it for each eye from the
// walk's point, with its fill (measure_fill). (See LadderLoad::engine_busy.) The eyes are ipd_m apart (--ipd): a
// run with wider eyes can send an object to a face this count leaves out.
std::vector<double> engine_seconds(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms,
                                   const dp::HostEngineConfig& config, int eyes, double ipd_m, const FillSamples& fill) {
  const host::RenderEngine engine(config);  // the run's own cost of a render
  const size_t n = scene.objects.size();
  std::vector<double> out(ms.t.size() * n);
  for (size_t k = 0; k < ms.t.size(); ++k) {
    const glm::dvec3 head = walk.position(ms.t[k]);
    for (size_t i = 0; i < n; ++i)
      out[k * n + i] = eyes * engine.seconds(drawing(scene.objects[i], ms.t[k], head, ipd_m, std::llround(fill.texels[k * n + i])));
  }
  return out;
}

// The run's priority rule for a ladder of `count` memories, memory 0 every `first` frames, each next one
// `ratio` times slower, at theta_t.
host::PriorityConfig ladder_priority(int count, int first, int ratio, double hz, double threshold_rad) {
  dp::MemoryConfig mc;
  mc.count = count;
  mc.update_frames = first;
  mc.update_ratio = ratio;
  host::PriorityConfig pc = host::PriorityConfig::of(mc, hz);
  pc.threshold_rad = threshold_rad;
  return pc;
}

// A ladder's load over the motion, by the run's own rule (PriorityScheduler::assign).
LadderLoad ladder_load(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms, double hz,
                       double threshold_rad, int count, int first, int ratio, const std::vector<double>& validity_s,
                       const std::vector<double>& engine_s, const FillSamples& fill, int eyes) {
  LadderLoad L;
  L.count = count;
  L.update_frames = first;
  L.update_ratio = ratio;
  L.objects.assign(static_cast<size_t>(count), 0.0);
  host::PriorityScheduler sched(scene, ladder_priority(count, first, ratio, hz, threshold_rad), 1);
  const size_t n = scene.objects.size();
  int64_t late = 0;
  for (size_t k = 0; k < ms.t.size(); ++k) {
    sched.assign(walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k]);
    for (size_t i = 0; i < n; ++i) {
      const int m = sched.belongs_in(i);
      L.objects[static_cast<size_t>(m)] += 1.0;
      L.triangles_per_s += static_cast<double>(scene.objects[i].mesh->triangles()) * hz / static_cast<double>(sched.frames_per_update(m));
      L.engine_busy += engine_s[k * n + i] * hz / static_cast<double>(sched.frames_per_update(m));
      L.texels_per_s += fill.texels[k * n + i] * eyes * hz / static_cast<double>(sched.frames_per_update(m));
      late += sched.period_s(m) > validity_s[k * n + i] ? 1 : 0;
    }
  }
  const double samples = static_cast<double>(ms.t.size());
  L.triangles_per_s /= samples;
  L.engine_busy /= samples;
  L.texels_per_s /= samples;
  for (double& o : L.objects) o /= samples;
  L.late_share = n ? static_cast<double>(late) / (samples * static_cast<double>(n)) : 0.0;
  return L;
}

// Where the run's priority rule puts each object at every sample of the motion (k * objects + i), for ladder L.
std::vector<int> rule_memories(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms, double hz,
                               double threshold_rad, const LadderLoad& L) {
  host::PriorityScheduler sched(scene, ladder_priority(L.count, L.update_frames, L.update_ratio, hz, threshold_rad), 1);
  const size_t n = scene.objects.size();
  std::vector<int> belongs(ms.t.size() * n);
  for (size_t k = 0; k < ms.t.size(); ++k) {
    sched.assign(walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k]);
    for (size_t i = 0; i < n; ++i) belongs[k * n + i] = sched.belongs_in(i);
  }
  return belongs;
}

// The engine a ladder needs (EngineNeed): where the rule puts each object at every sample of the motion, then the
// run's engine and its moves replayed at every display frame at a multiple of the configured engine's speed.
// (bisect false: only what the configured engine does, scale left 0; `known`: rule_memories for L, if computed already)
EngineNeed engine_need(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms, const dp::VideoTiming& vt,
                       double threshold_rad, const LadderLoad& L, const std::vector<double>& engine_s,
                       const dp::HostEngineConfig& engine, bool bisect = true, const std::vector<int>* known = nullptr) {
  const double hz = vt.refresh_hz();
  const host::PriorityScheduler sched(scene, ladder_priority(L.count, L.update_frames, L.update_ratio, hz, threshold_rad), 1);
  const size_t n = scene.objects.size(), N = static_cast<size_t>(L.count);
  const std::vector<int> computed = known ? std::vector<int>{} : rule_memories(scene, walk, ms, hz, threshold_rad, L);
  const std::vector<int>& belongs = known ? *known : computed;  // object i at sample k: k * n + i
  std::vector<int64_t> period(N);
  for (size_t m = 0; m < N; ++m) period[m] = sched.frames_per_update(static_cast<int>(m));
  const int64_t frames = static_cast<int64_t>(std::floor(ms.span_s * hz)) + 1;
  const int64_t step = std::max<int64_t>(1, std::llround(ms.step_s * hz));
  struct Replay {
    int64_t renders = 0, skipped = 0;
    double longest_s = 0;
  };
  const auto replay = [&](double scale) {
    Replay out;
    double engine_free = -std::numeric_limits<double>::infinity();
    std::vector<int64_t> swap(N, -1);  // the frame a memory's pending image is shown at (-1: none pending)
    std::vector<int> memory(n);        // where each object is: where the rule puts it at the start (HostSimulation::prime)
    for (size_t i = 0; i < n; ++i) memory[i] = belongs[i];
    std::vector<char> render(N), moved(N);
    std::vector<double> cost(N);
    for (int64_t f = 0; f < frames; ++f) {
      for (int64_t& w : swap)
        if (w >= 0 && w <= f) w = -1;
      const size_t k = std::min(static_cast<size_t>(f / step), ms.t.size() - 1);
      const double t = vt.frame_start_s(f);
      for (size_t m = 0; m < N; ++m) {
        const bool due = f % period[m] == 0;
        out.skipped += due && swap[m] >= 0 ? 1 : 0;
        render[m] = due && swap[m] < 0;
        moved[m] = 0;
        cost[m] = 0;
      }
      // An object moves only between memories rendering now, as far toward where it belongs as they allow.
      for (size_t i = 0; i < n; ++i) {
        const int from = memory[i];
        if (!render[static_cast<size_t>(from)]) continue;
        int to = belongs[k * n + i];
        while (to != from && !render[static_cast<size_t>(to)]) to += to > from ? -1 : 1;
        if (to != from) moved[static_cast<size_t>(from)] = moved[static_cast<size_t>(to)] = 1;
        memory[i] = to;
        cost[static_cast<size_t>(to)] += engine_s[k * n + i];
      }
      int64_t handover = -1;
      for (size_t m = 0; m < N; ++m) {
        if (!render[m]) continue;
        const double c = cost[m] / scale;
        engine_free = std::max(t, engine_free) + c;
        swap[m] = std::max(f + 1, static_cast<int64_t>(std::floor(engine_free * hz + 1e-9)) + 1);
        if (moved[m]) handover = std::max(handover, swap[m]);
        ++out.renders;
        out.longest_s = std::max(out.longest_s, c);
      }
      // Memories exchanging objects swap together, at the last of them to finish.
      for (size_t m = 0; m < N; ++m)
        if (moved[m]) swap[m] = handover;
    }
    return out;
  };
  EngineNeed need;
  const Replay at_one = replay(1.0);
  need.renders = at_one.renders;
  need.skipped = at_one.skipped;
  need.longest_render_s = at_one.longest_s;
  bool twice = false;  // a memory due twice within the motion: only then can a render be skipped
  for (size_t m = 0; m < N; ++m) twice |= frames > period[m];
  if (bisect && twice && std::any_of(engine_s.begin(), engine_s.end(), [](double c) { return c > 0; })) {
    double hi = 1.0, lo = 1.0;
    if (at_one.skipped > 0) {
      while (replay(hi).skipped > 0 && hi < 1e12) hi *= 2;
      lo = hi / 2;
    } else {
      while (replay(lo).skipped == 0 && lo > 1e-12) lo /= 2;
      hi = lo * 2;
    }
    while (hi / lo > 1 + 1e-6) {
      const double mid = std::sqrt(lo * hi);
      (replay(mid).skipped > 0 ? lo : hi) = mid;
    }
    need.scale = replay(lo).skipped > 0 ? hi : 0.0;  // none skipped even at 1e-12 of the engine: any engine carries it
  }
  need.fill_texels_per_s = need.scale * engine.texels_per_s;
  return need;
}

// What engine_need found, for the host.* row of a plan: the least engine, and what the configured one does.
std::string engine_need_text(const EngineNeed& need, const dp::HostEngineConfig& engine, double motion_s) {
  if (need.scale == 0) return "; no render can be skipped (no memory is due twice within the motion): any engine carries it";
  return ". Replayed at every frame as a run's engine renders (memories due rendered one after another, fastest first, a "
         "new image shown at the first vertical blank after it is done, a memory due again before then skipped), the least "
         "engine that skips no render over the " + printf_text("%.1f", motion_s) + " s is about " + printf_text("%.3g", need.scale) +
         " times this one (an estimate: each memory's objects rendered on their own at the fill's points, as its render "
         "draws them, and the fill interpolated between those points, a peak between two missed; "
         "more points, --fill-points, follow it closer): " + printf_text("%.4g", need.scale * engine.triangles_per_s) + " triangles/s, " +
         printf_text("%.4g", need.fill_texels_per_s) + " texels/s, " + printf_text("%.3g", engine.object_setup_s / need.scale) +
         " s set-up an object" +
         (need.skipped == 0 ? "; this one skips none of its " + std::to_string(need.renders) + " renders, the longest " +
                                  printf_text("%.3g", 1000 * need.longest_render_s) + " ms"
                            : "; this one skips " + std::to_string(need.skipped) + " updates (" + std::to_string(need.renders) +
                                  " rendered, the longest " + printf_text("%.3g", 1000 * need.longest_render_s) +
                                  " ms): a run shows it in host.memories[].skipped_overload") +
         " (objects moving between memories as a run moves them, memories exchanging them swapping together; not "
         "replayed are the tile and pool guards and memory.assignment)";
}

// Each object's memories over the motion at the planned ladder, by the run's own rule (the scheduler replayed
// over every sample, as ladder_load does): the fastest and slowest it is put in, every object of one name
// together (memory.assignment names objects), in the order the names first appear in the scene. A name
// memory.assignment cannot hold (empty, not printable ASCII, spaces around it, which its strings trim) is left
// to the rule alone and returned in `unnamed`. (A colon is held: a string's name ends at its last colon.)
std::vector<dp::ObjectAssignment> object_memories(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms,
                                                  double hz, double threshold_rad, const LadderLoad& L,
                                                  std::vector<std::string>& unnamed) {
  host::PriorityScheduler sched(scene, ladder_priority(L.count, L.update_frames, L.update_ratio, hz, threshold_rad), 1);
  const size_t n = scene.objects.size();
  std::vector<int> lo(n, L.count - 1), hi(n, 0);
  for (size_t k = 0; k < ms.t.size(); ++k) {
    sched.assign(walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k]);
    for (size_t i = 0; i < n; ++i) {
      lo[i] = std::min(lo[i], sched.belongs_in(i));
      hi[i] = std::max(hi[i], sched.belongs_in(i));
    }
  }
  std::vector<dp::ObjectAssignment> out;
  std::map<std::string, size_t> at;  // a name's entry in out
  for (size_t i = 0; i < n && !ms.t.empty(); ++i) {
    const std::string& name = scene.objects[i].name;
    const bool printable = std::all_of(name.begin(), name.end(), printable_ascii);
    if (name.empty() || !printable || name.front() == ' ' || name.back() == ' ') {
      if (std::find(unnamed.begin(), unnamed.end(), name) == unnamed.end()) unnamed.push_back(name);
      continue;
    }
    if (const auto e = at.find(name); e != at.end()) {
      out[e->second].fastest = std::min(out[e->second].fastest, lo[i]);
      out[e->second].slowest = std::max(out[e->second].slowest, hi[i]);
    } else {
      at[name] = out.size();
      out.push_back({name, lo[i], hi[i]});
    }
  }
  return out;
}

// A ladder's hardware display memory, as whole faces: the configuration `c` (face size, faces) with its
// memories and a depth code of `depth_bits`.
int64_t ladder_memory_bytes(dp::ArpConfig c, const LadderLoad& L, int depth_bits) {
  c.memory.count = L.count;
  c.memory.tiles.clear();
  c.memory.tile_pool.clear();
  c.memory.depth_bits = depth_bits;
  return display_memory_bytes(c);
}

// The narrowest depth code the parameter table allows.
int min_depth_bits() { return static_cast<int>(dp::arp_parameters().find("memory.depth_bits")->int_min); }

// The depth code's width for a ladder of `count` memories not measured (every ladder weighed but the planned
// one): with one there is nothing for the composition unit to compare, and the code only marks a texel
// written (its reserved value "empty", at any width), so the narrowest allowed; with more, the starting
// configuration's.
int depth_bits_for(int count, const dp::ArpConfig& base) { return count == 1 ? min_depth_bits() : base.memory.depth_bits; }

// The planned ladder's composition at every depth-code width (CompositionDepth): at kCompositionPoints points of
// the motion evenly spread (rendered_sample; the fill's, at its default --fill-points), each object in the memory
// the run's priority rule puts it in there (the scheduler replayed over every sample, as ladder_load does), from
// the walk's point, at face size S.
CompositionDepth measure_composition(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms,
                                     double hz, double threshold_rad, const LadderLoad& L, int S,
                                     const std::function<void(double)>& progress) {
  CompositionDepth out;
  host::PriorityScheduler sched(scene, ladder_priority(L.count, L.update_frames, L.update_ratio, hz, threshold_rad), 1);
  const size_t samples = ms.t.size(), points = std::min<size_t>(samples, kCompositionPoints);
  std::vector<int> memory_of(scene.objects.size());
  for (size_t k = 0, j = 0; k < samples && j < points; ++k) {
    sched.assign(walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k]);
    if (k != rendered_sample(j, points, samples)) continue;
    for (size_t i = 0; i < memory_of.size(); ++i) memory_of[i] = sched.belongs_in(i);
    add_composition_depth(scene, memory_of, L.count, ms.t[k], walk.position(ms.t[k]), S, out);
    ++j;
    progress(static_cast<double>(j) / static_cast<double>(points));
  }
  return out;
}

// The tiles each planned memory can ever be drawn on over the motion (TileBound in Planner.hpp). Each object is
// in the memory the run's priority rule puts it in (the scheduler replayed over every sample) or, while it
// waits to move, in one it was put in within the slowest memory's period before (it moves when both memories
// re-render together: at the latest by then; twice that is taken, and the window wraps round, as a run past
// the walk's end goes round it again); at every sample its box's texels on every present face
// (host::object_face_rect) go to each of those memories, for an eye within `margin` of the walk's point and
// the object grown by as far as its own animation moves it in a sample step (a render falls between samples).
TileBound bound_tiles(const host::Scene& scene, const host::WalkPath& walk, const MotionSamples& ms, double hz,
                      double threshold_rad, const LadderLoad& L, const dp::MemoryConfig& mc, double margin, double near_m) {
  const int S = mc.face_size, tpr = dp::DisplayMemoryBank::tiles_per_row_of(S);
  const size_t M = static_cast<size_t>(L.count);
  TileBound out;
  out.tiles_per_row = tpr;
  out.maps.assign(M, dp::TileMap(S, false));
  host::PriorityScheduler sched(scene, ladder_priority(L.count, L.update_frames, L.update_ratio, hz, threshold_rad), 1);
  const size_t n = scene.objects.size(), samples = ms.t.size();
  std::vector<std::array<glm::dvec3, 2>> box(n);
  for (size_t i = 0; i < n; ++i) box[i] = host::mesh_box(*scene.objects[i].mesh);
  std::vector<int> desired(samples * n);
  for (size_t k = 0; k < samples; ++k) {
    sched.assign(walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k]);
    for (size_t i = 0; i < n; ++i) desired[k * n + i] = sched.belongs_in(i);
  }
  // The waiting window in samples, and how many samples of it put each object in each memory (sliding).
  const double wait_s = 2.0 * static_cast<double>(dp::update_period_frames(L.update_frames, L.update_ratio, L.count - 1)) / hz;
  const size_t W = samples == 0 ? 0 : std::min(samples - 1, ms.step_s > 0 ? static_cast<size_t>(std::ceil(wait_s / ms.step_s)) : samples - 1);
  std::vector<int> in_window(n * M, 0);
  // Tiles drawn on at each sample, per memory (for the pool's cost): a tile counted once a sample.
  const size_t T2 = static_cast<size_t>(tpr) * static_cast<size_t>(tpr);
  std::vector<int64_t> stamp(M * 6 * T2, -1), count(samples * M, 0);
  auto ago = [&](size_t k, size_t back) { return (k + samples - back % samples) % samples; };  // sample k - back, round the walk
  auto at = [&](size_t k, size_t back) { return ago(k, back) * n; };
  for (size_t d = 1; d <= W && samples > 0; ++d)
    for (size_t i = 0; i < n; ++i) ++in_window[i * M + static_cast<size_t>(desired[at(0, d) + i])];
  for (size_t k = 0; k < samples; ++k) {
    for (size_t i = 0; i < n; ++i) ++in_window[i * M + static_cast<size_t>(desired[k * n + i])];  // the window: k - W .. k
    const glm::dvec3 head = walk.position(ms.t[k]);
    for (size_t i = 0; i < n; ++i) {
      size_t lo = 0, hi = M - 1;
      while (in_window[i * M + lo] == 0) ++lo;
      while (in_window[i * M + hi] == 0) --hi;
      const host::SceneObject& o = scene.objects[i];
      const double moves = host::animation_reach_m(o, ms.t[k], ms.step_s);
      for (int f = 0; f < 6; ++f) {
        if (!mc.faces[static_cast<size_t>(f)]) continue;
        const host::TexelRect rc = host::object_face_rect(o, box[i], ms.t[k], head, margin + moves, f, S, near_m);
        if (rc.empty()) continue;
        for (size_t m = lo; m <= hi; ++m) {
          host::each_tile(rc, [&](int tx, int ty) {
            out.maps[m].set(f, tx, ty, true);
            int64_t& st = stamp[(m * 6 + static_cast<size_t>(f)) * T2 + static_cast<size_t>(ty * tpr + tx)];
            if (st != static_cast<int64_t>(k)) {
              st = static_cast<int64_t>(k);
              ++count[k * M + m];
            }
            return true;
          });
        }
      }
    }
    for (size_t i = 0; i < n; ++i) --in_window[i * M + static_cast<size_t>(desired[at(k, W) + i])];  // leaves the window
  }
  for (const auto& m : out.maps) out.per_memory.push_back(m.tiles());
  // The pool: an image's tiles and those of the image shown while it is drawn -- drawn an update period
  // before, or two where a render was skipped (its memory's last image not yet swapped in) or a swap waited for
  // a slower memory (an object changing memory): the most of the samples one to two periods before, round the
  // walk as above. More late renders in a row than that can take more.
  out.at_once.assign(M, 0);
  out.pooled.assign(M, 0);
  for (size_t m = 0; m < M && samples > 0; ++m) {
    const double period_s = static_cast<double>(dp::update_period_frames(L.update_frames, L.update_ratio, static_cast<int>(m))) / hz;
    const size_t P = ms.step_s > 0 ? std::max<size_t>(1, static_cast<size_t>(std::ceil(period_s / ms.step_s - 1e-9))) : 1;
    for (size_t k = 0; k < samples; ++k) {
      out.at_once[m] = std::max(out.at_once[m], count[k * M + m]);
      int64_t shown = 0;
      for (size_t back = P; back <= 2 * P; ++back) shown = std::max(shown, count[ago(k, back) * M + m]);
      out.pooled[m] = std::max(out.pooled[m], count[k * M + m] + shown);
    }
  }
  return out;
}

// Every tile of the faces `c` has, as memory.tiles lists it.
std::string every_tile_text(const dp::ArpConfig& c) {
  dp::TileMap t(c.memory.face_size, true);
  for (int f = 0; f < 6; ++f)
    if (c.memory.faces[static_cast<size_t>(f)] == 0)
      for (int ty = 0; ty < t.tiles_per_row(); ++ty)
        for (int tx = 0; tx < t.tiles_per_row(); ++tx) t.set(f, tx, ty, false);
  return t.text();
}

// The tiles each memory of `c` holds for a tile bound: only those it can be drawn on where that takes less
// than whole faces (and `tile_sparse`), every tile of the faces present otherwise (a memory drawn on nearly
// everywhere would pay for whole 32 x 32 slots and a tile table for little; one no object reaches keeps its
// faces, as an empty scene keeps the cube). `texts` is memory.tiles (empty: every memory whole).
struct HeldTiles {
  std::vector<std::string> texts;
  std::vector<bool> sparse;  // per memory
};
HeldTiles held_tiles(const dp::ArpConfig& c, const TileBound& b, bool tile_sparse) {
  HeldTiles out;
  bool any = false;
  for (size_t m = 0; m < b.maps.size(); ++m) {
    const int64_t reach = b.per_memory[m];
    const bool sparse = tile_sparse && reach > 0 && tiles_take_less(c, reach);
    any |= sparse;
    out.sparse.push_back(sparse);
    out.texts.push_back(sparse ? b.maps[m].text() : every_tile_text(c));
  }
  if (!any) out.texts.clear();
  return out;
}

// Each memory's tile pool for a tile bound (memory.tile_pool; empty: none anywhere): the slots the motion needs
// (TileBound::pooled) where a pool takes less than the tiles held_tiles gives it, or its whole faces.
std::vector<int64_t> pools_taken(const dp::ArpConfig& c, const TileBound& b, const HeldTiles& held) {
  std::vector<int64_t> pools(b.maps.size(), 0);
  bool any = false;
  for (size_t m = 0; m < b.maps.size(); ++m) {
    const int64_t reach = b.per_memory[m];
    const int64_t held_bits = held.sparse[m] ? bank_bits_tiled(c, reach) : bank_bits_whole(c);
    if (reach > 0 && bank_bits_pooled(c, b.pooled[m]) < held_bits) {
      pools[m] = b.pooled[m];
      any = true;
    }
  }
  if (!any) pools.clear();
  return pools;
}

// `c`'s hardware display memory holding the tiles of `b` as held_tiles puts them, and with `tile_pool` a pool
// wherever pools_taken takes one (a pooled memory's tables address every tile of its faces).
int64_t bytes_as_planned(dp::ArpConfig c, const TileBound& b, bool tile_sparse, bool tile_pool) {
  const HeldTiles held = held_tiles(c, b, tile_sparse);
  c.memory.tiles = held.texts;
  c.memory.tile_pool = tile_sparse && tile_pool ? pools_taken(c, b, held) : std::vector<int64_t>{};
  for (size_t m = 0; m < c.memory.tile_pool.size(); ++m)
    if (c.memory.tile_pool[m] > 0 && !c.memory.tiles.empty()) c.memory.tiles[m] = every_tile_text(c);
  return display_memory_bytes(c);
}

// Region priority rendering's load over the motion with `count` memories at theta_t (RegionLoad): the scene
// segmented along columns of `size_m` (as a run segments it), the run's region rule stepped at every display
// frame of the motion as if every memory were free to render, each update rendering the pieces of that
// memory for each eye, sent to every face their bound reaches (the engine's cost of set-up and triangles).
RegionLoad region_load(const host::Scene& scene, const host::WalkPath& walk, const HeadMotion& head_motion, const MotionSamples& ms,
                       const dp::VideoTiming& vt, double threshold_rad,
                       int count, int S, double size_m, const dp::HostEngineConfig& config, int eyes, double ipd_m,
                       const FillSamples& fill) {
  RegionLoad out;
  const double hz = vt.refresh_hz();
  out.size_m = size_m;
  out.margin_m = host::swept_margin_m(size_m);
  std::unique_ptr<host::RegionGrid> grid;
  try {
    grid = std::make_unique<host::RegionGrid>(scene.extent_min, scene.extent_max, size_m, false, "region size");
  } catch (const InputError& e) {
    out.refused = e.reason();
    return out;
  }
  const host::Segmented seg = host::segment_scene(scene, *grid, true);
  out.segments = static_cast<int64_t>(seg.scene.objects.size());
  std::vector<double> piece_triangles(scene.objects.size(), 0.0);  // of each object, its pieces' together (cutting adds some)
  for (size_t i = 0; i < seg.scene.objects.size(); ++i) piece_triangles[seg.source[i]] += static_cast<double>(seg.scene.objects[i].mesh->triangles());
  host::RegionConfig rc;
  rc.region_size_m = size_m;
  rc.margin_m = out.margin_m;
  rc.memories = count;
  rc.threshold_rad = threshold_rad;
  host::RegionScheduler sched(*grid, rc, S, walk.position(0), "region size");
  const host::RenderEngine engine(config);
  const int64_t frames = std::max<int64_t>(1, std::llround(ms.span_s * hz));
  const size_t n = scene.objects.size(), samples = ms.t.size();
  const int64_t step = std::max<int64_t>(1, std::llround(ms.step_s * hz));  // frames between samples
  std::vector<double> period_s(static_cast<size_t>(count));  // the region rule's: a threshold distance walked, a frame at least
  for (int m = 0; m < count; ++m)
    period_s[static_cast<size_t>(m)] = walk.speed() > 0 ? std::max(sched.threshold_distance(m) / walk.speed(), 1 / hz) : host::kForever;
  double triangles = 0, busy_s = 0, pieces = 0, sent = 0;
  std::vector<int> memory_of(seg.scene.objects.size());
  HeadTurnRate rate(walk, head_motion, ms.span_s);
  int64_t late = 0;
  for (int64_t f = 0; f < frames; ++f) {
    const double t = vt.frame_start_s(f);
    const glm::dvec3 head = walk.position(t);
    const host::EyeTurn turn = rate.eyes_at(t, 1.0 / hz, ipd_m);
    const host::RegionScheduler::Step st = sched.step(head, true);
    for (size_t i = 0; i < seg.scene.objects.size(); ++i) {  // each piece's memory this frame, once
      memory_of[i] = sched.memory_of_object(seg.region[i], seg.span.empty() ? nullptr : &seg.span[i]);
      late += period_s[static_cast<size_t>(memory_of[i])] >
              host::object_validity(seg.scene.objects[i], head, walk.speed(), turn, t, threshold_rad).period_s();
    }
    for (const int m : st.update) {
      sched.rendered(m, head);
      for (size_t i = 0; i < seg.scene.objects.size(); ++i) {
        if (memory_of[i] != m) continue;
        const host::SceneObject& o = seg.scene.objects[i];
        // Its fill: its object's at the sample at or before (measure_fill), by its share of the pieces' triangles.
        const size_t src = seg.source[i], k = std::min(samples - 1, static_cast<size_t>(f / step));
        const host::RenderStats drawn = drawing(
            o, t, head, ipd_m, std::llround(fill.texels[k * n + src] * static_cast<double>(o.mesh->triangles()) / std::max(1.0, piece_triangles[src])));
        triangles += static_cast<double>(o.mesh->triangles());
        pieces += 1;
        sent += static_cast<double>(drawn.triangles);
        busy_s += eyes * engine.seconds(drawn);
      }
    }
  }
  out.reassignments = sched.reassignments();
  out.triangles_per_s = triangles * hz / static_cast<double>(frames);
  out.pieces_per_s = pieces * hz / static_cast<double>(frames);
  out.triangles_sent_per_s = sent * hz / static_cast<double>(frames);
  out.late_share = seg.scene.objects.empty() ? 0.0 : static_cast<double>(late) / (static_cast<double>(frames) * static_cast<double>(seg.scene.objects.size()));
  out.engine_busy = busy_s * hz / static_cast<double>(frames);
  return out;
}

// What tells one ladder from another.
std::array<int, 3> ladder_key(const LadderLoad& L) { return {L.count, L.update_frames, L.update_ratio}; }

std::string ladder_text(const LadderLoad& L) {
  std::string s = std::to_string(L.count) + (L.count == 1 ? " memory" : " memories") + " every ";
  for (int m = 0; m < L.count; ++m)
    s += (m ? ", " : "") + std::to_string(dp::update_period_frames(L.update_frames, L.update_ratio, m));
  return s + " frames";
}

}  // namespace

Plan make_plan(const PlanRequest& r) {
  if (r.memories.scene.empty()) throw InputError("--scene", "", "a plan is made for a scene: name one (a file, or gallery)");
  if (!(r.texel_error >= 0) || !std::isfinite(r.texel_error) || r.texel_error > 1000)
    throw InputError("--texel-error", "", "must be 0 .. 1000 texels (0: what the starting configuration measures)");
  // theta_t: --threshold-deg, else the starting configuration's (0: one texel at the planned face size).
  const double theta_deg = r.threshold_deg.value_or(r.base.memory.threshold_deg);
  HostSpec::threshold_rad(theta_deg);  // its range
  if (r.walk.empty())
    throw InputError("--walk", "", "a plan is made for a motion: a walk file, or gallery (--speed 0: standing at its first point)");
  if (!(r.load_tolerance >= 0) || r.load_tolerance > 10) throw InputError("--load-tolerance", "", "must be 0 .. 10");
  if (r.fill_points < 2 || r.fill_points > kMaxSamples)
    throw InputError("--fill-points", std::to_string(r.fill_points), "must be 2 .. " + std::to_string(kMaxSamples));
  if (r.memory_limit_mib && !(*r.memory_limit_mib >= 0 && *r.memory_limit_mib <= 1e9))
    throw InputError("--memory-limit", printf_text("%g", *r.memory_limit_mib), "must be 0 (none) .. 1e9 MiB");
  if (r.depth_error && !(*r.depth_error >= 0 && *r.depth_error <= 1))
    throw InputError("--depth-error", "", "must be a share of the composed texels, 0 .. 1");
  config::check(r.base, r.base_source);
  // The starting configuration's fill is measured at its own face size (its figures beside the plan's).
  check_plan_fits_memory(r.base.memory.face_size, r.base.timing.eyes, r.base_source, "memory.face_size",
                         "the starting configuration's, where its own load is measured");
  Plan p;
  p.config = r.base;
  // The tiles and the assignment are planned anew (a plan started from a plan's configuration: its lists name
  // its own memories, and would make every ladder with fewer invalid), and the starting configuration's memory
  // weighed as whole faces, as every ladder is.
  p.config.memory.tiles.clear();
  p.config.memory.tile_pool.clear();
  p.config.memory.assignment.clear();
  dp::ArpConfig base_whole = r.base;
  base_whole.memory.tiles.clear();
  base_whole.memory.tile_pool.clear();
  base_whole.memory.assignment.clear();
  auto progress = [&](int step, double f, const std::string& w) {
    if (r.progress) r.progress(step, kPlanSteps, f, w);
  };

  // The motion, then the scene: a bad option or trace is refused before the scene is loaded (the gallery: about 1 s).
  HostSpec hs;
  hs.walk = r.walk;
  hs.walk_speed = r.walk_speed;
  const host::WalkPath walk = hs.make_walk();
  const dp::VideoTiming timing(r.base.timing);
  const double hz = timing.refresh_hz();
  const double ipd_given = r.memories.checked_ipd_m();                     // --ipd
  const double ipd_m = r.base.timing.eyes > 1 ? ipd_given : 0.0;  // (the run's rule: HostSimulation)
  r.head.check();
  // The plan reads a trace twice, its samples and its bytes (plan.motion_hash): standard input can be read only once.
  if (r.head.trace == "-") throw InputError("--trace", "-", "a plan reads the trace more than once: give it as a file");
  // A trace's samples are read once, for every pass below.
  HeadMotion head_motion = r.head;
  if (!head_motion.trace.empty())
    head_motion.trace_poses =
        std::make_shared<const std::vector<tracker::PoseSample>>(read_planned_trace(head_motion.trace, walk_span_s(walk)));
  const MotionSamples ms = sample_motion(walk, head_motion, timing, ipd_m);
  // A trace that begins after the motion does: its first sample stands for the head before it, as in a run
  // (sim::Session says the same) -- said, not refused; with no sample within the walk, the head never turns.
  if (head_motion.trace_poses && !head_motion.trace_poses->empty() && head_motion.trace_poses->front().time_ps > 0) {
    const double first_s = ps_to_seconds(head_motion.trace_poses->front().time_ps);
    p.warnings.push_back("the trace " + head_motion.trace + " starts at " + printf_text("%.6f", first_s) +
                         " s, after the motion's start at 0 s: the head before it holds its first sample" +
                         (first_s > ms.span_s ? ", through the whole " + printf_text("%.6g", ms.span_s) + " s planned over (no sample falls within it)"
                                              : std::string()));
  }
  // The face size's limits are the options' too (the display, the lens): checked before the scene as well.
  const auto [amin, acentre] = pixel_angles(r.base);
  auto face_for = [](double pixel_rad) {
    return static_cast<int>(std::clamp(std::ceil(1.0 / std::tan(pixel_rad / 2.0) - 1e-9), 1.0, 16384.0));
  };
  const bool finest = r.resolve == "finest";
  if (!finest && r.resolve != "centre") throw InputError("--resolve", r.resolve, "must be centre or finest");
  const int S = face_for(finest ? amin : acentre);
  check_plan_fits_memory(S, r.base.timing.eyes, r.base_source, "lens.fov_deg",
                         "planned from the angle a display pixel subtends after the lens (--resolve " + r.resolve + ")");
  progress(kStepScene, 0.0, "the scene");
  const host::Scene scene = r.memories.load_scene();
  p.scene_name = scene.name;
  p.scene_hash = host::scene_hash(scene);
  p.objects = scene.objects.size();
  p.triangles = scene.triangles();
  p.motion_s = ms.span_s;
  p.samples = static_cast<int>(ms.t.size());
  p.config.plan.scene_hash = p.scene_hash;
  p.config.plan.motion_hash = motion_hash(walk, r.head);
  p.config.plan.ipd_m = ipd_given;

  // 1. Face size: the largest texel (at a face's centre, 2 atan(1/S)) no coarser than the finest pixel.
  // (Any display pixel can look at any texel as the head turns, so the largest texel is held to the pixel:
  // S above, from the pixel angles.)
  progress(kStepPixelAngles, 0.0, "pixel angles");
  p.pixel_angle_min_rad = amin;
  p.pixel_angle_centre_rad = acentre;
  p.config.memory.face_size = S;
  p.choices.push_back({"memory.face_size", std::to_string(S),
                       "a display pixel after the lens subtends " + printf_text("%.4f", rad_to_deg(acentre) * 60.0) +
                           " arcmin at the lens centre, " + printf_text("%.4f", rad_to_deg(amin) * 60.0) +
                           " at the finest (the panel's corners); a face's largest texel, at its centre, subtends 2 atan(1/S): S = " +
                           std::to_string(S) + " is the smallest no coarser than the " + (finest ? "finest pixel" : "centre pixel") +
                           " (" + printf_text("%.4f", rad_to_deg(2.0 * std::atan(1.0 / S)) * 60.0) + " arcmin; --resolve " +
                           (finest ? "centre gives " + std::to_string(face_for(acentre)) : "finest gives " + std::to_string(face_for(amin))) +
                           "); a finer face is not resolved"});

  // 2. Widths: the narrowest the harness keeps within the bound at the planned face size.
  WidthSearch search(r, p);
  if (!r.size_widths) {
    p.choices.push_back({"datapath.*", widths_text(p.config.widths), "kept from " + r.base_source + " (--keep-widths): not measured"});
  } else {
    // The runs expected, for the progress (set once, so its share never goes back): the starting widths' two, each
    // width's binary search twice over (a second pass that changes nothing ends at once), the planned widths' own.
    int expected = 3;
    for (const WidthKey& k : kWidths) expected += 2 * static_cast<int>(std::ceil(std::log2(p.config.widths.*k.field - k.lo() + 1.0)));
    search.expect(expected);
    progress(kStepWidths, 0.0, "datapath widths");
    p.texel_error_base = search.error(r.base);
    p.texel_error_bound = r.texel_error > 0 ? r.texel_error : p.texel_error_base;
    dp::ArpConfig c = p.config;
    double err = search.error(c);
    for (int wider = 1; err > p.texel_error_bound && wider <= 16; wider *= 2) {
      // Wider than the start, every width by the same number of bits (1, 2, 4 ...), then the top of its
      // range: the last is the best this datapath can do.
      const dp::DatapathWidths before = c.widths;
      c = p.config;
      for (const WidthKey& k : kWidths) c.widths.*k.field = wider == 16 ? k.hi() : std::min(k.hi(), c.widths.*k.field + wider);
      bool same = true;
      for (const WidthKey& k : kWidths) same = same && c.widths.*k.field == before.*k.field;
      if (!same) err = search.error(c);  // (every width already at its top: measured)
      if ((wider == 16 || same) && !(err <= p.texel_error_bound))
      {
        // (%.3g: a bound measured at the widest widths is a few hundred-thousandths, "0.0000" in fixed point)
        const std::string best = "the best achievable is " + printf_text("%.3g", err) + " texels (every width at its widest)";
        if (r.texel_error > 0)
          throw InputError("--texel-error", printf_text("%g", p.texel_error_bound),
                           "no datapath widths meet it at face size " + std::to_string(S) + ": " + best);
        throw InputError(r.base_source, "datapath.*",
                         "no --texel-error was given, so the bound is what this configuration measures at its face size " +
                             std::to_string(r.base.memory.face_size) + ", " + printf_text("%.3g", p.texel_error_bound) +
                             " texels; no datapath widths meet it at the planned face size " + std::to_string(S) + ": " + best +
                             "; give --texel-error at least that");
      }
    }
    for (int pass = 0; pass < 2; ++pass) {
      bool changed = false;
      for (const WidthKey& k : kWidths) {
        // Binary search the smallest value still within the bound (error grows as a width narrows).
        int lo = k.lo(), hi = c.widths.*k.field;
        while (lo < hi) {
          const int mid = lo + (hi - lo) / 2;
          dp::ArpConfig t = c;
          t.widths.*k.field = mid;
          if (search.error(t) <= p.texel_error_bound) hi = mid;
          else lo = mid + 1;
        }
        if (hi != c.widths.*k.field) {
          c.widths.*k.field = hi;
          changed = true;
        }
      }
      if (!changed) break;
    }
    p.texel_error_planned = search.error(c);
    p.config.widths = c.widths;
    p.choices.push_back({"datapath.*", widths_text(c.widths),
                         "the narrowest each (tried one at a time, twice over) with the accuracy harness's largest texel-position "
                         "error at face size " + std::to_string(S) + " within " + printf_text("%.4f", p.texel_error_bound) + " texels" +
                             (r.texel_error > 0 ? " (--texel-error)" : " (what " + r.base_source + " measures: --texel-error)") +
                             ": measured " + printf_text("%.4f", p.texel_error_planned) + " over the quick harness sample, " +
                             std::to_string(p.harness_runs) + " harness runs"});
  }

  // Faces any object reaches over the motion, by the renderers' own test (host::sphere_meets_face) with each
  // bound grown by what the samples do not see: an eye is up to half the distance between the eyes from the
  // walk's point, and the head moves up to a sample step between samples. (An animated object's own motion
  // between samples is not covered beyond that: the samples are display frames, or at most kMaxSamples.)
  const double near_m = host::DepthCode{}.near_m;
  const double margin = 0.5 * ipd_given + walk.speed() * ms.step_s;
  for (const double t : ms.t) {
    const glm::dvec3 head = walk.position(t);
    for (const host::SceneObject& o : scene.objects) {
      const host::Sphere b = o.world_bound(t);
      for (int f = 0; f < 6; ++f)
        if (host::sphere_meets_face(b.center - head, b.radius + margin, f, near_m)) p.faces_reached[static_cast<size_t>(f)] = true;
    }
  }
  for (int f = 0; f < 6; ++f) p.config.memory.faces[static_cast<size_t>(f)] = p.faces_reached[static_cast<size_t>(f)] ? 1 : 0;
  if (scene.objects.empty()) p.config.memory.faces = {1, 1, 1, 1, 1, 1};  // nothing to place: keep the plain cube (background only)

  // 3. Display memories: the ladder of update periods with the least host load, in as few memories as
  // come within the tolerance of the least.
  p.threshold_rad = theta_deg > 0 ? deg_to_rad(theta_deg) : dp::texel_angle_rad(S);
  const size_t n = scene.objects.size();
  std::vector<double> validity_s(ms.t.size() * n, host::kForever);
  p.fastest_need_frames = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < ms.t.size(); ++k) {
    const glm::dvec3 eye = walk.position(ms.t[k]);
    for (size_t i = 0; i < n; ++i) {
      const double v = host::object_validity(scene.objects[i], eye, walk.speed(), ms.turn[k], ms.t[k], p.threshold_rad).period_s();
      validity_s[k * n + i] = v;
      p.fastest_need_frames = std::min(p.fastest_need_frames, v * hz);
    }
  }
  // Memory 0 no slower than the fastest need (every object can be kept within theta_t), a power of two,
  // and within the motion (at least a second): what never needs updating is updated once a walk.
  const double cap = std::min(static_cast<double>(dp::MemoryConfig::kMaxUpdateFrames), std::max(hz, p.motion_s * hz));
  int first = 1;
  while (first * 2 <= std::min(p.fastest_need_frames, cap)) first *= 2;
  std::vector<LadderLoad> candidates;
  const dp::HostEngineConfig& engine = p.config.host;
  const int eyes = p.config.timing.eyes;
  const std::string fill_what = "fill (" + std::to_string(std::min<size_t>(ms.t.size(), static_cast<size_t>(r.fill_points))) + " renders)";
  progress(kStepFill, 0.0, fill_what);
  const FillSamples fill = measure_fill(scene, walk, ms, S, r.fill_points, [&](double f) { progress(kStepFill, f, fill_what); });
  p.fill_points = fill.points;
  const std::vector<double> engine_s = engine_seconds(scene, walk, ms, engine, eyes, ipd_m, fill);
  if (n == 0) {
    candidates.push_back(ladder_load(scene, walk, ms, hz, p.threshold_rad, 1, 1, 2, validity_s, engine_s, fill, eyes));
  } else {
    for (int count = 1; count <= dp::kCompositionInputs; ++count)
      for (const int ratio : {2, 3, 4}) {
        progress(kStepLadders, static_cast<double>(count - 1) / dp::kCompositionInputs, "ladders");
        dp::ArpConfig t = p.config;
        t.memory.count = count;
        t.memory.update_frames = first;
        t.memory.update_ratio = ratio;
        if (!dp::validate(t).empty()) continue;  // the slowest period beyond the key's range
        if (count > 1 && static_cast<double>(dp::update_period_frames(first, ratio, count - 1)) > cap) break;  // beyond the motion
        candidates.push_back(ladder_load(scene, walk, ms, hz, p.threshold_rad, count, first, ratio, validity_s, engine_s, fill, eyes));
        if (count == 1) break;  // the ratio does not matter with one memory
      }
  }
  // Only the ladders the engine can carry (engine_busy <= 1). None: an error naming the least it
  // would be busy at this theta_t and at any theta_t (every object in one memory updated once every `cap`
  // frames, the slowest a ladder goes).
  const auto least_busy = *std::min_element(candidates.begin(), candidates.end(),
                                            [](const LadderLoad& a, const LadderLoad& b) { return a.engine_busy < b.engine_busy; });
  if (least_busy.engine_busy > 1) {
    double floor_busy = 0;  // every object at every sample once every `cap` frames, mean over the motion
    for (const double e : engine_s) floor_busy += e * hz / cap / static_cast<double>(ms.t.size());
    // Name the rate that takes most of the engine's time: the fill's, or the triangles' (with set-up).
    const bool fill_most = least_busy.texels_per_s / engine.texels_per_s > 0.5 * least_busy.engine_busy;
    throw InputError(
        r.base_source, fill_most ? "host.texels_per_s" : "host.triangles_per_s",
        "the rendering engine (" + printf_text("%.3g", engine.triangles_per_s) + " triangles/s, " + printf_text("%.3g", engine.texels_per_s) +
            " texels/s, " + printf_text("%.3g", engine.object_setup_s) + " s set-up an object, " + std::to_string(eyes) + (eyes == 1 ? " eye" : " eyes") + ") cannot carry this scene at theta_t " +
            printf_text("%.4f", rad_to_deg(p.threshold_rad)) + " deg: every ladder keeps it busy more than the whole of each second -- the least " +
            printf_text("%.3g", least_busy.engine_busy) + " s a second (" + ladder_text(least_busy) + ")" +
            (floor_busy > 1 ? "; no theta_t helps: even rendered once every " + printf_text("%.0f", cap) + " frames it needs " + printf_text("%.3g", floor_busy) +
                                  " s a second"
                            : "; a larger --threshold-deg lowers it (at the slowest, once every " + printf_text("%.0f", cap) + " frames: " +
                                  printf_text("%.3g", floor_busy) + " s a second)"));
  }
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(), [](const LadderLoad& L) { return L.engine_busy > 1; }),
                   candidates.end());
  // Only the ladders within the memory limit (--memory-limit; by default the starting configuration's display
  // memory): a ladder's hardware figure at the planned face size and faces, with the depth code it would
  // start from (the planned ladder's may narrow after, never widen) -- as whole faces, or, where those are
  // over the limit, as it would be planned: each memory holding only the tiles its objects can be drawn on
  // over the motion where that takes less (step 5 below; not with --whole-faces). None: an error naming the
  // least. (The default limits the ladder, not the face size: where even the smallest ladder at the planned
  // face size takes more than the starting configuration, the limit is that ladder's.)
  const double limit_mib = r.memory_limit_mib.value_or(static_cast<double>(display_memory_bytes(base_whole)) / 1048576.0);
  std::map<std::array<int, 3>, TileBound> bounds;  // by ladder: the tile bounds worked out (the planned one's reused)
  if (limit_mib > 0) {
    p.memory_limit_bytes = static_cast<int64_t>(std::floor(limit_mib * 1048576.0));
    for (size_t j = 0; j < candidates.size(); ++j) {
      LadderLoad& L = candidates[j];
      progress(kStepLimitTiles, static_cast<double>(j) / static_cast<double>(candidates.size()),
               "ladders' tiles");
      L.memory_bytes_whole = ladder_memory_bytes(p.config, L, depth_bits_for(L.count, r.base));
      if (!r.tile_sparse || L.memory_bytes_whole <= p.memory_limit_bytes) continue;
      const TileBound& b = bounds[ladder_key(L)] = bound_tiles(scene, walk, ms, hz, p.threshold_rad, L, p.config.memory, margin, near_m);
      dp::ArpConfig c = p.config;
      c.memory.count = L.count;
      c.memory.depth_bits = depth_bits_for(L.count, r.base);
      L.memory_bytes_tiled = bytes_as_planned(c, b, true, r.tile_pool && r.weigh_pools);
    }
    const auto least = *std::min_element(candidates.begin(), candidates.end(), [](const LadderLoad& a, const LadderLoad& b) {
      return a.memory_bytes_weighed() < b.memory_bytes_weighed();
    });
    if (!r.memory_limit_mib) p.memory_limit_bytes = std::max(p.memory_limit_bytes, least.memory_bytes_weighed());
    if (least.memory_bytes_weighed() > p.memory_limit_bytes)  // (only a limit given: the default is at least the least's)
      throw InputError("--memory-limit", printf_text("%g", limit_mib),
                       "no ladder the engine carries fits at face size " + std::to_string(S) + ": the least takes " +
                           printf_text("%.1f", static_cast<double>(least.memory_bytes_weighed()) / 1048576.0) + " MiB (" + ladder_text(least) +
                           (least.memory_bytes_tiled > 0 && least.memory_bytes_tiled < least.memory_bytes_whole
                                ? (r.tile_pool && r.weigh_pools ? ", tile-sparse or pooled" : ", tile-sparse")
                                : "") + ")");
    const size_t before = candidates.size();
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                    [&](const LadderLoad& L) { return L.memory_bytes_weighed() > p.memory_limit_bytes; }),
                     candidates.end());
    p.ladders_over_limit = static_cast<int>(before - candidates.size());
  }
  for (LadderLoad& L : candidates)
    if (L.memory_bytes_whole == 0) L.memory_bytes_whole = ladder_memory_bytes(p.config, L, depth_bits_for(L.count, r.base));
  // The starting configuration at its own theta_t (one texel at its own face size unless given).
  const double base_threshold = theta_deg > 0 ? p.threshold_rad : dp::texel_angle_rad(r.base.memory.face_size);
  std::vector<double> base_validity = validity_s;
  if (base_threshold != p.threshold_rad)
    for (size_t k = 0; k < ms.t.size(); ++k)
      for (size_t i = 0; i < n; ++i)
        base_validity[k * n + i] =
            host::object_validity(scene.objects[i], walk.position(ms.t[k]), walk.speed(), ms.turn[k], ms.t[k], base_threshold)
                .period_s();
  // Its fill at its own face size.
  const bool base_fill_own = r.base.memory.face_size != S && n > 0;
  const std::string base_fill_what = "fill at face " + std::to_string(r.base.memory.face_size) + " (" +
                                     std::to_string(std::min<size_t>(ms.t.size(), static_cast<size_t>(r.fill_points))) + ")";
  if (base_fill_own) progress(kStepBaseFill, 0.0, base_fill_what);
  const FillSamples base_fill =
      base_fill_own ? measure_fill(scene, walk, ms, r.base.memory.face_size, r.fill_points, [&](double f) { progress(kStepBaseFill, f, base_fill_what); })
                    : fill;
  const std::vector<double> base_engine_s =
      r.base.memory.face_size == S ? engine_s : engine_seconds(scene, walk, ms, engine, eyes, ipd_m, base_fill);
  // What the configured engine skips with each, replayed at every frame (EngineNeed): plan.md's ladder table. The
  // choice below stays on the mean load. Then the least engine for the planned ladder and the starting
  // configuration's, each a bisection of some 30 replays (the progress's weights).
  p.best = *std::min_element(candidates.begin(), candidates.end(),
                             [](const LadderLoad& a, const LadderLoad& b) { return a.triangles_per_s < b.triangles_per_s; });
  p.planned = p.best;
  for (const LadderLoad& L : candidates)  // the fewest memories within the tolerance, then the least load
    if (L.triangles_per_s <= p.best.triangles_per_s * (1 + r.load_tolerance) &&
        (L.count < p.planned.count || (L.count == p.planned.count && L.triangles_per_s < p.planned.triangles_per_s)))
      p.planned = L;
  p.base_ladder = n == 0 ? p.planned
                         : ladder_load(scene, walk, ms, hz, base_threshold, r.base.memory.count, r.base.memory.update_frames,
                                       r.base.memory.update_ratio, base_validity, base_engine_s, base_fill, eyes);
  // For the least engines of the planned ladder and the starting configuration: each memory's objects rendered on
  // their own at the fill's points, as the memory's render in a run draws them (an object of a slow memory is no
  // longer hidden behind a nearer one of a fast memory). One memory: the scene's fill is that already.
  const std::vector<int> planned_belongs = rule_memories(scene, walk, ms, hz, p.threshold_rad, p.planned);
  const std::vector<int> base_belongs = rule_memories(scene, walk, ms, hz, base_threshold, p.base_ladder);
  const bool planned_own = n > 0 && p.planned.count > 1, base_own = n > 0 && p.base_ladder.count > 1;
  const std::string memory_fill_what =
      "fill by memory (" + std::to_string(std::min<size_t>(ms.t.size(), static_cast<size_t>(r.fill_points))) + ")";
  if (planned_own || base_own) progress(kStepMemoryFill, 0.0, memory_fill_what);
  const FillSamples planned_fill =
      planned_own ? measure_fill(scene, walk, ms, S, r.fill_points, [&](double f) { progress(kStepMemoryFill, 0.5 * f, memory_fill_what); },
                                 &planned_belongs)
                  : fill;
  const FillSamples base_memory_fill =
      base_own ? measure_fill(scene, walk, ms, r.base.memory.face_size, r.fill_points,
                              [&](double f) { progress(kStepMemoryFill, 0.5 + 0.5 * f, memory_fill_what); }, &base_belongs)
               : base_fill;
  const std::vector<double> planned_engine_s =
      planned_own ? engine_seconds(scene, walk, ms, engine, eyes, ipd_m, planned_fill) : engine_s;
  const std::vector<double> base_memory_engine_s =
      base_own ? engine_seconds(scene, walk, ms, engine, eyes, ipd_m, base_memory_fill) : base_engine_s;
  // What the configured engine skips with each ladder, replayed at every frame (EngineNeed): plan.md's ladder table
  // (the planned ladder's with its memories' own fill, the others' with the scene's, lower). The choice above is on
  // the mean load. Then the least engine for the planned ladder and the starting configuration, each a bisection of
  // some 30 replays (the progress's weights).
  const double replays = static_cast<double>(candidates.size()) + 60.0;
  for (size_t j = 0; j < candidates.size(); ++j) {
    progress(kStepEngine, static_cast<double>(j) / replays, "engine replay");
    const bool planned = ladder_key(candidates[j]) == ladder_key(p.planned);
    candidates[j].skipped = engine_need(scene, walk, ms, timing, p.threshold_rad, candidates[j], planned ? planned_engine_s : engine_s,
                                        engine, false, planned ? &planned_belongs : nullptr)
                                .skipped;
  }
  progress(kStepEngine, static_cast<double>(candidates.size()) / replays, "least engine");
  p.planned_need = engine_need(scene, walk, ms, timing, p.threshold_rad, p.planned, planned_engine_s, engine, true, &planned_belongs);
  progress(kStepEngine, (static_cast<double>(candidates.size()) + 30.0) / replays, "least engine");
  p.base_need = n == 0 ? p.planned_need
                       : engine_need(scene, walk, ms, timing, base_threshold, p.base_ladder, base_memory_engine_s, engine, true,
                                     &base_belongs);
  p.ladders = candidates;
  p.config.memory.count = p.planned.count;
  p.config.memory.update_frames = p.planned.update_frames;
  p.config.memory.update_ratio = p.planned.update_ratio;
  p.config.memory.threshold_deg = theta_deg;  // what the ladder was sized for: a run with the plan renders by it
  // The tiles of each planned memory any of its objects can be drawn on over the motion (step 5 below; bounded
  // here, as the depth code's width is held to the memory limit with them).
  if (const auto b = bounds.find(ladder_key(p.planned)); b != bounds.end()) {
    p.tiles = b->second;
  } else {
    progress(kStepPlannedTiles, 0.0, "planned tiles");
    p.tiles = bound_tiles(scene, walk, ms, hz, p.threshold_rad, p.planned, p.config.memory, margin, near_m);
  }
  // The depth code: with one memory only a written flag; with several, the narrowest that composes them
  // within the bound, measured.
  const auto texel_bits = [&] {
    return "each texel " + std::to_string(p.config.memory.color_bits() + p.config.memory.depth_bits) + " bits instead of " +
           std::to_string(r.base.memory.color_bits() + r.base.memory.depth_bits);
  };
  if (p.planned.count == 1) {
    p.config.memory.depth_bits = depth_bits_for(1, r.base);
    p.choices.push_back({"memory.depth_bits", std::to_string(p.config.memory.depth_bits),
                         "one memory: the composition unit has nothing to compare, and the depth code only marks a texel "
                         "written (its reserved value \"empty\", at any width), so the narrowest allowed; " + texel_bits()});
  } else {
    const std::string depth_what = "depth code (" + std::to_string(std::min<size_t>(ms.t.size(), static_cast<size_t>(kCompositionPoints))) +
                                   " x " + std::to_string(p.planned.count) + ")";
    progress(kStepDepthCode, 0.0, depth_what);
    p.composition = measure_composition(scene, walk, ms, hz, p.threshold_rad, p.planned, S,
                                        [&](double f) { progress(kStepDepthCode, f, depth_what); });
    const int base_bits = r.base.memory.depth_bits;
    // The default bound is the starting width's own share: never wider than it. A bound given may call for
    // any width; none meeting it is refused, naming the best.
    p.depth_error_bound = r.depth_error.value_or(p.composition.share(base_bits));
    int top = r.depth_error ? CompositionDepth::kMaxBits : base_bits;
    // Never wider than the memory limit allows (the ladder was held to it at the starting width).
    while (p.memory_limit_bytes > 0 && top > base_bits) {
      dp::ArpConfig c = p.config;
      c.memory.depth_bits = top;
      if (bytes_as_planned(c, p.tiles, r.tile_sparse, r.tile_pool && r.weigh_pools) <= p.memory_limit_bytes) break;
      --top;
    }
    p.config.memory.depth_bits = p.composition.narrowest(min_depth_bits(), top, p.depth_error_bound);
    if (p.config.memory.depth_bits == 0)
      throw InputError("--depth-error", printf_text("%g", p.depth_error_bound),
                       "no depth code composes the planned " + std::to_string(p.planned.count) +
                           " memories within it: the best achievable is " + printf_text("%.3g", p.composition.share(top)) + " at " +
                           std::to_string(top) + " bits" +
                           (top < (r.depth_error ? CompositionDepth::kMaxBits : base_bits)
                                ? " (a wider code would take more display memory than the limit, --memory-limit)"
                                : " (surfaces of different memories at the same distance tie at any width)"));
    const int w = p.config.memory.depth_bits;
    std::string why = std::to_string(p.planned.count) + " memories composed by depth code (the smallest wins, a tie goes to the "
                      "lower memory), measured at " + std::to_string(p.composition.points) +
                      " points of the motion: each memory's objects (the run's priority rule) rendered from the walk's point at "
                      "face size " + std::to_string(S) + " and composed at every width; of " +
                      std::to_string(p.composition.composed) + " texels where two or more memories hold a surface, " +
                      "composed from a memory whose surface is not the nearest: " + printf_text("%.3g", p.composition.share(w)) + " at " +
                      std::to_string(w) + (w == 1 ? " bit" : " bits");
    if (w > min_depth_bits()) why += ", " + printf_text("%.3g", p.composition.share(w - 1)) + " at " + std::to_string(w - 1);
    why += ", " + printf_text("%.3g", p.composition.share(base_bits)) + " at " + std::to_string(base_bits) + " (" + r.base_source +
           "'s); the narrowest whose share, and every wider width's, is within " + printf_text("%.3g", p.depth_error_bound) +
           (r.depth_error ? " (--depth-error)" : " (what " + r.base_source + "'s width measures: --depth-error)") + "; " +
           texel_bits();
    if (w == min_depth_bits() && p.composition.wrong[static_cast<size_t>(w)] == 0)
      why += " (every nearer surface is in a faster memory: a tie, won by the lower memory, is right)";
    p.choices.push_back({"memory.depth_bits", std::to_string(w), why});
  }
  if (n == 0) {
    p.choices.push_back({"memory.count, memory.update_frames, memory.update_ratio", "1, 1, 2",
                         "the scene is empty: one memory holds the background, nothing is ever rendered into it"});
  } else {
    std::string why = "over " + std::to_string(p.samples) + " points of the motion (" + printf_text("%.1f", p.motion_s) +
                      " s) at theta_t " + printf_text("%.4f", rad_to_deg(p.threshold_rad)) + " deg, the fastest any object needs " +
                      (std::isfinite(p.fastest_need_frames) ? std::string("re-rendering is every ") + printf_text("%.1f", p.fastest_need_frames) + " frames"
                                                            : std::string("re-rendering is never (nothing moves)")) +
                      ", so memory 0 updates every " + std::to_string(first) + " (at most the motion's frames, at least a second's)" +
                      "; of " + std::to_string(candidates.size()) + " ladders (1 .. " +
                      std::to_string(dp::kCompositionInputs) + " memories, ratio 2, 3, 4" +
                      (p.memory_limit_bytes > 0 ? ", the engine can carry, within " +
                                                      printf_text("%.1f", static_cast<double>(p.memory_limit_bytes) / 1048576.0) +
                                                      " MiB of display memory" + (r.tile_sparse ? std::string(r.tile_pool && r.weigh_pools ? " (as whole faces, or as planned tile-sparse or with tile pools, --weigh-pools, where those are over)"
                                                                                                         : " (as whole faces, or as planned tile-sparse where those are over)")
                                                                    : std::string()) + " (--memory-limit" +
                                                      (r.memory_limit_mib ? std::string(")")
                                                       : p.memory_limit_bytes > display_memory_bytes(base_whole)
                                                           ? ": the least any ladder takes at this face size, more than " + r.base_source + "'s)"
                                                           : ": " + r.base_source + "'s)") +
                                                      (p.ladders_over_limit > 0 ? ", " + std::to_string(p.ladders_over_limit) + " more left out for their memory" : std::string())
                                                : std::string(", the engine can carry")) +
                      ") the least host load is " +
                      printf_text("%.3g", p.best.triangles_per_s) + " triangles/s (" + ladder_text(p.best) + "); " +
                      ladder_text(p.planned) + " is the fewest within " + printf_text("%.0f", 100 * r.load_tolerance) +
                      " % of it: " + printf_text("%.3g", p.planned.triangles_per_s) + " triangles/s, against " +
                      printf_text("%.3g", p.base_ladder.triangles_per_s) + " for " + r.base_source + " (" + ladder_text(p.base_ladder) +
                      ", at its own theta_t " + printf_text("%.4f", rad_to_deg(base_threshold)) + " deg)";
    if (p.fastest_need_frames < 1)
      why += "; some objects need more than one update a frame: the display rate cannot keep them within theta_t";
    p.choices.push_back({"memory.count, memory.update_frames, memory.update_ratio",
                         std::to_string(p.planned.count) + ", " + std::to_string(p.planned.update_frames) + ", " +
                             std::to_string(p.planned.update_ratio),
                         why});
  }
  p.choices.push_back({"memory.threshold_deg", printf_text("%g", theta_deg),
                       theta_deg > 0 ? "the theta_t the memories were sized for (--threshold-deg, or the starting configuration's): "
                                       "a run with this plan renders by it unless its own --threshold-deg says otherwise"
                                     : "0: one texel at the planned face size (" + printf_text("%.4f", rad_to_deg(p.threshold_rad)) +
                                           " deg), the theta_t the memories were sized for"});

  // The object-to-memory assignment: where the rule puts each object over this motion, written as keys (the
  // starting configuration's was cleared at the start).
  if (p.planned.count > 1 && n > 0) {
    std::vector<std::string> unnamed;
    const std::vector<dp::ObjectAssignment> a = object_memories(scene, walk, ms, hz, p.threshold_rad, p.planned, unnamed);
    std::vector<int> pinned(static_cast<size_t>(p.planned.count), 0);
    int moving = 0;
    for (const dp::ObjectAssignment& e : a) {
      p.config.memory.assignment.push_back(e.text());
      if (e.fastest == e.slowest) ++pinned[static_cast<size_t>(e.fastest)];
      else ++moving;
    }
    std::string in_one;  // "memory 2: 1, memory 3: 4"
    for (size_t m = 0; m < pinned.size(); ++m)
      if (pinned[m] > 0) in_one += (in_one.empty() ? "" : ", ") + ("memory " + std::to_string(m)) + ": " + std::to_string(pinned[m]);
    p.assignment = a;
    p.choices.push_back(
        {"memory.assignment", std::to_string(a.size()) + " names (plan.md's last table)",
         "the memories the run's priority rule puts each object in over the " + std::to_string(p.samples) +
             " points of the motion at the planned ladder and theta_t (every object of one name together): " +
             std::to_string(a.size() - static_cast<size_t>(moving)) + " stay in one memory" +
             (in_one.empty() ? std::string() : " (" + in_one + ")") + ", " + std::to_string(moving) +
             " move between memories as the user walks. A run over this motion keeps within them, so they change nothing "
             "there; over another motion they bound the rule, and a name edited to one memory pins its objects there" +
             (r.base.memory.assignment.empty() ? std::string() : " (" + r.base_source + "'s memory.assignment is not kept)") +
             (unnamed.empty() ? std::string()
                              : "; " + std::to_string(unnamed.size()) + " names the key cannot hold (empty, not printable ASCII, "
                                "or spaces at an end) are left to the rule")});
  } else {
    p.choices.push_back({"memory.assignment", "none",
                         n == 0 ? "the scene is empty: no object to place"
                                : "one memory: every object is in it"});
  }

  // 4. Faces (worked out before the memories, whose hardware size they set).
  const int present = p.config.memory.faces_present();
  p.choices.push_back(
      {"memory.faces", face_list(p.config.memory.faces),
       scene.objects.empty() ? "the scene is empty: no face is ever written; the cube is kept whole (it shows the background)"
       : present == 6        ? "every face is reached by some object at some point of the motion"
                             : "faces " + p.config.memory.absent_face_names() +
                                   " are never reached by any object's bounding sphere, grown by half the distance between the eyes (--ipd) "
                                   "and a sample step, at any point of the motion (the renderers' face test, host::sphere_meets_face): "
                                   "left out of every memory, " +
                                   std::to_string(6 - present) + " of 6 faces' storage saved; a run that draws on them "
                                   "loses those texels and says so"});
  // 5. The tiles of each memory any of its objects can be drawn on over the motion: what a tile-sparse display
  // memory (a tile table per bank, and only those tiles' storage) needs for this scene and motion.
  {
    std::vector<int64_t> banks;  // every eye's bank of each memory: the same bound
    for (int e = 0; e < p.config.timing.eyes; ++e) banks.insert(banks.end(), p.tiles.per_memory.begin(), p.tiles.per_memory.end());
    p.memory_bytes_tiled = display_memory_bytes_tiled(p.config, banks);
    p.memory_bytes_whole = display_memory_bytes(p.config);
    // Memory by memory: only the tiles where that takes less than whole faces (held_tiles).
    const int64_t whole = int64_t{p.config.memory.faces_present()} * p.tiles.tiles_per_row * p.tiles.tiles_per_row;
    const double whole_one = static_cast<double>(bank_bits_whole(p.config)) / 8;  // one eye's bank, whole faces
    HeldTiles held = held_tiles(p.config, p.tiles, r.tile_sparse);
    std::string value;
    int64_t pooled_bits = 0;  // one eye's banks with a tile pool where that takes less
    std::vector<int64_t> pools(p.tiles.maps.size(), 0);
    const std::vector<int64_t> cheaper = pools_taken(p.config, p.tiles, held);  // (the figure, whatever the flags)
    for (size_t m = 0; m < p.tiles.maps.size(); ++m) {
      const int64_t reach = p.tiles.per_memory[m];
      const double tiled_one = static_cast<double>(bank_bits_tiled(p.config, reach)) / 8;
      value += (m ? "; memory " : "memory ") + std::to_string(m) + ": " +
               (held.sparse[m] ? std::to_string(reach) + " of " + std::to_string(whole) + " tiles"
                               : "every tile (" + std::to_string(reach) + " of " + std::to_string(whole) + " can be drawn on)") +
               " (" + printf_text("%.1f", tiled_one / 1048576.0) + " MiB an eye tile-sparse, " + printf_text("%.1f", whole_one / 1048576.0) + " whole" +
               (reach > 0 ? "; at most " + std::to_string(p.tiles.at_once[m]) + " at once, a pool of " + std::to_string(p.tiles.pooled[m]) +
                                " slots " + printf_text("%.1f", static_cast<double>(bank_bits_pooled(p.config, p.tiles.pooled[m])) / 8 / 1048576.0) + " MiB"
                          : std::string()) + ")";
      const bool pool = m < cheaper.size() && cheaper[m] > 0;
      pooled_bits += pool ? bank_bits_pooled(p.config, cheaper[m]) : held.sparse[m] ? bank_bits_tiled(p.config, reach) : bank_bits_whole(p.config);
      if (pool && r.tile_sparse && r.tile_pool) pools[m] = cheaper[m];
    }
    p.memory_bytes_pooled = (int64_t{p.config.timing.eyes} * pooled_bits + 7) / 8;
    p.memory_bytes_fixed_tiles = bytes_as_planned(p.config, p.tiles, r.tile_sparse, false);
    // A memory with a pool holds every tile of the faces present: its tile tables address them all, and the pool
    // bounds how many are stored at once.
    bool any_pool = false, any_fixed = false;
    for (size_t m = 0; m < pools.size(); ++m) {
      any_pool |= pools[m] > 0;
      if (pools[m] > 0 && !held.texts.empty()) held.texts[m] = every_tile_text(p.config);
      any_fixed |= pools[m] == 0 && held.sparse[m];
    }
    if (!any_fixed) held.texts.clear();
    p.config.memory.tiles = held.texts;
    if (any_pool) p.config.memory.tile_pool = pools;
    p.choices.push_back(
        {"memory.tiles", value,
         "each memory's objects' boxes (grown as for the faces above, and by how far an animated object moves in a sample "
         "step) projected on every face present at every point of the motion, an object counted in every memory it is "
         "put in within twice the slowest memory's period: a memory holds only those tiles (whole 32 x 32 slots, and a "
         "tile table for its bank) where that takes less than whole faces" +
             (!r.tile_sparse ? std::string(" (--whole-faces: every tile everywhere)") : std::string()) + "; all memories " +
             printf_text("%.1f", static_cast<double>(p.memory_bytes_fixed_tiles) / 1048576.0) + " MiB so against " +
             printf_text("%.1f", static_cast<double>(p.memory_bytes_whole) / 1048576.0) + " MiB as whole faces" +
             (any_pool ? " (a memory with a tile pool below holds every tile instead: its pool bounds how many at once)" : "") +
             ". A run of this plan, with the same distance between the eyes (--ipd), object-level priority (no --baseline, "
             "--regions) and the planned theta_t, draws within these (a texel drawn outside them is lost, counted in "
             "footprint.texels_lost_off_tiles, and the run warns); its report gives the tiles it drew on, every eye's banks "
             "together (footprint.display_memory_tiles_drawn_on)"});
    std::string pool_value;
    for (size_t m = 0; m < pools.size(); ++m) pool_value += (m ? ", " : "") + std::to_string(pools[m]);
    p.choices.push_back(
        {"memory.tile_pool", any_pool ? "[" + pool_value + "]" : "none",
         "a tile pool per bank (slots both buffers share, a tile given a slot as its own texels are first drawn and the slot "
         "freed when its buffer is cleared for the next render) needs, per memory, the most tiles drawn on at one point of the "
         "motion and at one to two update periods before together (the image being drawn and the one shown; two periods for "
         "a render skipped or a swap held for a slower memory): " +
             printf_text("%.1f", static_cast<double>(p.memory_bytes_pooled) / 1048576.0) + " MiB, each memory pooled where that takes "
             "less than its tiles or whole faces, against " + printf_text("%.1f", static_cast<double>(p.memory_bytes_fixed_tiles) / 1048576.0) +
             " MiB with fixed tiles" +
             (!r.tile_sparse ? std::string(": not taken (--whole-faces)")
              : !r.tile_pool ? std::string(": not taken (--fixed-tiles)")
              : !any_pool    ? std::string(": no memory's pool takes less")
                             : std::string(". The bound is from the motion's sampled points, not a proof: a run whose pool "
                                           "is full loses the texels of the tiles it had no slot for, counts them in "
                                           "footprint.texels_lost_tile_pool_full and warns; its "
                                           "footprint.display_memory_tiles_most_at_once gives the slots it used"))});
  }
  p.not_decided.push_back("a face size per memory (one face size for every memory: the composition unit composes each bilinear "
                          "tap across the memories at the same texel position)");
  p.not_decided.push_back("a bound on the fill between the " + std::to_string(fill.points) +
                          " points of the motion rendered for it (--fill-points): each other point interpolates the two around "
                          "it, so an object that comes close between two of them and leaves again is under-counted");
  if (p.planned.count > 1)
    p.not_decided.push_back("a bound on the depth code's composition: it is measured from the walk's point at the " +
                            std::to_string(p.composition.points) + " points rendered, each memory as if rendered there and "
                            "then; a run renders a slower memory from where the head was at its last update");
  // 6. FIFO depths: the smallest the configuration allows. In this pipeline nothing but an injected stall
  // holds a stage back -- the host writes through its own port (timed.host_*), never the pipeline's read
  // port -- so at any host load each inter-stage FIFO holds one token and the scan-out FIFO the issue slack
  // plus one (a run's report: fifos[].max_occupancy).
  p.config.timed.fifo_depth = p.config.timed.min_fifo_depth();
  p.choices.push_back({"timed.fifo_depth", std::to_string(p.config.timed.fifo_depth),
                       "the smallest allowed (timed.issue_slack_cycles + 2): the host writes the display memories through "
                       "their own write port, never the pipeline's read port, so no host load stalls a stage; unstalled, "
                       "each inter-stage FIFO holds one token and the scan-out FIFO the issue slack and one (a cycle-level "
                       "run's report: fifos[].max_occupancy)"});
  // 6b. The host's write port into display memory: at its configured clock, as many texels a clock as store the fill of
  // the engine the planned ladder needs (EngineNeed) as fast as that engine fills -- a port narrower than the engine's
  // fill would slow every render below the need.
  {
    const int64_t clock = p.config.timed.host_clock_hz;
    const int64_t widest = dp::arp_parameters().find("timed.host_texels_per_cycle")->int_max;
    const double port_fill = p.planned_need.fill_texels_per_s;
    const double wanted = std::ceil(port_fill / static_cast<double>(clock));
    p.config.timed.host_texels_per_cycle = static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(widest)));
    p.choices.push_back(
        {"timed.host_texels_per_cycle", std::to_string(p.config.timed.host_texels_per_cycle),
         (p.planned_need.scale > 0
              ? "the write port stores texels as fast as the engine the planned ladder needs fills them (" + printf_text("%.4g", port_fill) +
                    " texels/s: host.* below; that engine has no time to spare, so a narrower port, lengthening its fill, "
                    "would skip renders) at timed.host_clock_hz " + printf_text("%.4g", static_cast<double>(clock)) + " Hz" +
                    (wanted > static_cast<double>(widest) ? ": it needs " + printf_text("%.0f", wanted) + " texels a clock, over the key's " +
                                                                std::to_string(widest) + " -- a faster timed.host_clock_hz"
                                                          : std::string())
              : std::string("no render can be skipped (no memory is due twice within the motion): any engine and a one-texel port carry it")) +
             ". A run renders through the modelled engine (host.*), which the port's width does not slow; the port carries "
             "host write jobs (the cycle-level testbenches')"});
  }
  // 7. Region priority rendering against object-level, with the planned memories: regions are taken where they
  // carry the motion with less host load than the planned ladder by more than the load tolerance, the engine
  // carries them and, as whole faces (regions place objects by region, not where their tiles are) with the
  // starting configuration's depth code (the composition was measured for object-level), they fit the limit.
  p.config.memory.region_size_m = 0;
  p.config.memory.region_margin_m = dp::ArpConfig{}.memory.region_margin_m;
  std::string region_why;
  const RegionLoad* taken = nullptr;
  if (r.weigh_regions && n > 0 && walk.speed() == 0)
    region_why = "regions not weighed: standing, the region rule never updates a memory (nothing to compare)";
  if (r.weigh_regions && n > 0 && walk.speed() > 0) {
    const std::array<double, 3> sizes = {2.0, 4.0, 8.0};
    for (const double size : sizes) {
      progress(kStepRegions, static_cast<double>(p.regions.size()) / static_cast<double>(sizes.size()),
               "regions (" + printf_text("%g", size) + " m)");
      p.regions.push_back(region_load(scene, walk, head_motion, ms, timing, p.threshold_rad, p.planned.count, S, size, engine, eyes, ipd_m, fill));
    }
    const RegionLoad* best = nullptr;
    for (const RegionLoad& R : p.regions)
      if (R.refused.empty() && R.engine_busy <= 1 && R.late_share <= p.planned.late_share &&
          (!best || R.triangles_per_s < best->triangles_per_s))
        best = &R;
    dp::ArpConfig by_regions = p.config;
    if (best) {
      by_regions.memory.region_size_m = best->size_m;
      by_regions.memory.region_margin_m = best->margin_m;
      by_regions.memory.tiles.clear();
      by_regions.memory.tile_pool.clear();
      by_regions.memory.assignment.clear();
      by_regions.memory.depth_bits = std::max(p.config.memory.depth_bits, depth_bits_for(p.planned.count, r.base));
    }
    const bool saves = best && best->triangles_per_s < p.planned.triangles_per_s * (1 - r.load_tolerance);
    const bool fits = p.memory_limit_bytes == 0 || (best && display_memory_bytes(by_regions) <= p.memory_limit_bytes);
    region_why = !best ? "no region size the world and the engine allow keeps objects within theta_t as well as objects do (updated "
                         "slower than needed: " + printf_text("%.2f %%", 100 * p.planned.late_share) + " by objects)"
                 : "the least region load is " + printf_text("%.3g", best->triangles_per_s) + " triangles/s with " +
                       printf_text("%g", best->size_m) + " m regions (" + std::to_string(p.planned.count) + (p.planned.count == 1 ? " memory" : " memories") +
                       ", margin " + printf_text("%g", best->margin_m) + " m), against " + printf_text("%.3g", p.planned.triangles_per_s) +
                       " by objects" + (saves ? "" : ": not less by more than " + printf_text("%.0f", 100 * r.load_tolerance) + " %") +
                       (saves && !fits ? ": less, but as whole faces with the starting depth code over the memory limit" : "") +
                       (saves && fits && !r.take_regions
                            ? ": less, but not taken without --take-regions -- the plan bounds each piece's displacement by theta_t, "
                              "not the tearing between pieces of one object in memories updated at different times, nor the seams "
                              "the depth code composes (measured by a run against the truth: docs/planning.md)"
                            : "");
    if (saves && fits && r.take_regions) {
      p.config = by_regions;
      taken = best;
      // The rows above that regions change, rewritten: every tile, the depth code, the memories' updates.
      for (PlanChoice& c : p.choices) {
        const std::string then = " -- replaced: region priority rendering was taken (memory.region_size_m below)";
        if (c.keys == "memory.assignment") {
          c.value = "none";
          c.reason = "regions place objects by region: the object-level assignment (plan.md's last table) is not used" + then;
        } else if (c.keys == "memory.tile_pool") {
          c.value = "none";
          c.reason = "regions place objects by region, not where their tiles are: no pool was sized for them" + then;
        } else if (c.keys == "memory.tiles") {
          c.value = "every tile of the faces present";
          c.reason = "regions place objects by region, not where their tiles are: the object-level bound (plan.md's figures, "
                     "the .tiles.png) is not used" + then;
        } else if (c.keys == "memory.depth_bits") {
          c.value = std::to_string(p.config.memory.depth_bits);
          c.reason = "the wider of the width measured for object-level and " + r.base_source + "'s (the composition was not "
                     "measured for regions)" + then;
        } else if (c.keys.rfind("memory.count", 0) == 0) {
          c.reason += "; by regions the memories update on need (the user walking a memory's threshold distance), not at "
                      "these periods" + then;
        }
      }
    }
  }
  const double chosen = p.config.memory.region_size_m;
  p.choices.push_back({"memory.region_size_m, memory.region_margin_m",
                       printf_text("%g", chosen) + ", " + printf_text("%g", p.config.memory.region_margin_m),
                       (chosen > 0 ? "region priority rendering (Chow, Pose & Regan 2005): " + region_why +
                                         "; every tile of each memory, depth code " + std::to_string(p.config.memory.depth_bits) + " bits"
                                   : "object-level priority rendering (each object in the memory its own validity needs), which the ladder, "
                                     "tiles and depth code above are planned for" +
                                         (region_why.empty() ? std::string(r.weigh_regions ? "" : " (--objects-only)") : "; " + region_why)) +
                           (r.base.memory.region_size_m > 0 && chosen == 0
                                ? " (" + r.base_source + "'s region size " + printf_text("%g", r.base.memory.region_size_m) + " m is not kept)"
                                : std::string()) +
                           (p.regions.empty() ? std::string() : "; each size weighed by the run's region rule stepped at every frame of the motion (plan.md)")});
  if (taken)  // its figures: the whole faces it holds, and the tiles not used
    p.memory_bytes_whole = display_memory_bytes(p.config);
  if (!p.config.memory.assignment.empty())  // (regions, taken, clear it)
    p.not_decided.push_back("an assignment other than the rule's: memory.assignment is where the rule put each object over the "
                            "motion (objects of one name together), not chosen to spare moves between memories or pool slots");
  p.not_decided.push_back("the region size at other memory counts than the ladder's, and the tearing between regions (measured by a "
                          "run, not the plan); the host clock (timed.host_clock_hz, kept: the port's width above is sized at it)");
  p.choices.push_back({"host.* (the rendering engine)", "kept from " + r.base_source,
                       (taken ? "by regions it is busy " + printf_text("%.3g", taken->engine_busy) + " s of each second (plan.md's region "
                                "table); by objects it carries the planned ladder: busy "
                              : std::string("it carries the planned ladder: busy ")) + printf_text("%.3g", p.planned.engine_busy) +
                           " s of each second (every object drawn for each eye at each update of its memory: its set-up, "
                           "its triangles sent to every face its bound reaches from both eyes, " +
                           printf_text("%.0f", 1000 * ipd_given) + " mm apart (--ipd), and its fill, " +
                           printf_text("%.3g", p.planned.texels_per_s) + " texels/s against the engine's " + printf_text("%.3g", engine.texels_per_s) +
                           ", measured by rendering the scene at " + std::to_string(fill.points) +
                           " points of the motion, each other point interpolating the two around it; ladders it could not carry were not considered)" +
                           engine_need_text(p.planned_need, engine, p.motion_s)});
  p.memory_bytes_planned = display_memory_bytes(p.config);
  p.memory_bytes_base = display_memory_bytes(base_whole);
  config::check(p.config, "the plan");

  return p;
}

host::RgbImage plan_tiles_image(const Plan& p) {
  const int tpr = p.tiles.tiles_per_row, rows = static_cast<int>(p.tiles.maps.size());
  const int face_px = tpr * kTilePixels, gap = kTilePixels;
  host::RgbImage img(gap + 6 * (face_px + gap), gap + rows * (face_px + gap));
  for (int m = 0; m < rows; ++m)
    for (int f = 0; f < 6; ++f) {
      const bool present = p.config.memory.faces[static_cast<size_t>(f)] != 0;
      for (int ty = 0; ty < tpr; ++ty)
        for (int tx = 0; tx < tpr; ++tx) {
          const bool in = present && p.tiles.reachable(m, f, tx, ty);
          const uint8_t c[3] = {static_cast<uint8_t>(!present ? 90 : in ? 235 : 45), static_cast<uint8_t>(!present ? 0 : in ? 225 : 45),
                                static_cast<uint8_t>(!present ? 0 : in ? 160 : 45)};
          for (int y = 0; y < kTilePixels; ++y)
            for (int x = 0; x < kTilePixels; ++x) {
              uint8_t* px = img.px(gap + f * (face_px + gap) + tx * kTilePixels + x, gap + m * (face_px + gap) + ty * kTilePixels + y);
              px[0] = c[0];
              px[1] = c[1];
              px[2] = c[2];
            }
        }
    }
  return img;
}

std::string plan_config_text(const Plan& p) {
  std::string text = config::to_json(p.config).dump(2) + "\n";
  // A plan every command can read back: its object names (memory.assignment) must not take it past the limit.
  if (text.size() > config::kMaxConfigBytes)
    throw InputError("--scene", p.scene_name,
                     "the plan's configuration would be " + std::to_string(text.size()) + " bytes (memory.assignment names " +
                         std::to_string(p.config.memory.assignment.size()) + " objects), more than the " +
                         std::to_string(config::kMaxConfigBytes) + " a configuration file may be");
  return text;
}

std::string plan_markdown(const Plan& p, const PlanRequest& r) {
  std::string s = "# Plan for scene " + p.scene_name + "\n\n";
  s += "Scene: " + std::to_string(p.objects) + " objects, " + std::to_string(p.triangles) + " triangles (plan.scene_hash " +
       std::to_string(p.scene_hash) + "). Motion: " + (r.walk.empty() ? std::string("the head still at the gallery walk's start") : "walk " + r.walk) +
       (r.head.given() ? ", the head turning with " + r.head.describe() + " on top" : "") +
       ", " + printf_text("%.1f", p.motion_s) + " s, " + std::to_string(p.samples) + " points evaluated (plan.motion_hash " +
       std::to_string(p.config.plan.motion_hash) + "), the eyes " + printf_text("%g", 1000 * r.memories.checked_ipd_m()) +
       " mm apart (--ipd; plan.ipd_m: a run with another warns). Started from " + r.base_source + ".\n\n";
  for (const std::string& w : p.warnings) s += "**Warning**: " + w + ".\n\n";
  s += "| keys | value | reason |\n| --- | --- | --- |\n";
  for (const PlanChoice& c : p.choices) s += "| " + c.keys + " | " + c.value + " | " + c.reason + " |\n";
  s += "\n## Figures\n\n| | " + r.base_source + " | plan |\n| --- | --- | --- |\n";
  s += "| face size | " + std::to_string(r.base.memory.face_size) + " | " + std::to_string(p.config.memory.face_size) + " |\n";
  if (p.harness_runs > 0)
    s += "| texel error (harness, texels) | " + printf_text("%.4f", p.texel_error_base) + " (at " + std::to_string(r.base.memory.face_size) +
         ") | " + printf_text("%.4f", p.texel_error_planned) + " (bound " + printf_text("%.4f", p.texel_error_bound) + ") |\n";
  s += "| display memories | " + ladder_text(p.base_ladder) + " | " + ladder_text(p.planned) + " |\n";
  s += "| host load, triangles/s | " + printf_text("%.4g", p.base_ladder.triangles_per_s) + " | " + printf_text("%.4g", p.planned.triangles_per_s) + " |\n";
  s += "| host fill, texels/s (the scene rendered whole: a lower bound; the least engine's replay renders each memory's own) | " + printf_text("%.4g", p.base_ladder.texels_per_s) + " | " + printf_text("%.4g", p.planned.texels_per_s) + " |\n";
  s += "| rendering engine busy, s a second (with that fill) | " + printf_text("%.3g", p.base_ladder.engine_busy) + " | " + printf_text("%.3g", p.planned.engine_busy) + " |\n";
  const auto need = [](const EngineNeed& e) { return e.scale == 0 ? std::string("any") : printf_text("%.3g", e.scale); };
  s += "| least engine that skips no render, times host.* (replayed every frame) | " + need(p.base_need) + " | " + need(p.planned_need) + " |\n";
  s += "| renders skipped by host.*, of those due (replayed) | " + std::to_string(p.base_need.skipped) + " of " +
       std::to_string(p.base_need.renders + p.base_need.skipped) + " | " + std::to_string(p.planned_need.skipped) + " of " +
       std::to_string(p.planned_need.renders + p.planned_need.skipped) + " |\n";
  s += "| object-samples updated slower than they need | " + printf_text("%.2f %%", 100 * p.base_ladder.late_share) + " | " +
       printf_text("%.2f %%", 100 * p.planned.late_share) + " |\n";
  s += "| display memory, whole faces (hardware, MiB) | " + printf_text("%.1f", static_cast<double>(p.memory_bytes_base) / 1048576.0) + " | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_whole) / 1048576.0) + " |\n";
  const std::string unused = p.config.memory.region_size_m > 0 ? ", object-level: not used by regions" : "";
  s += "| display memory, tile-sparse (the tiles the motion can draw on" + unused + ", MiB) | | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_tiled) / 1048576.0) + " |\n";
  s += "| display memory, tile-sparse with fixed tiles where they take less (memory.tiles alone" + unused + ", MiB) | | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_fixed_tiles) / 1048576.0) + " |\n";
  s += "| display memory with a tile pool per bank where that takes less (memory.tile_pool" + unused + ", MiB) | | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_pooled) / 1048576.0) + " |\n";
  const std::string held_as = std::string(p.config.memory.tiles.empty() ? "every tile" : "memory.tiles") +
                              (p.config.memory.tile_pool.empty() ? "" : ", memory.tile_pool");
  s += "| display memory as planned (" + held_as + ", hardware, MiB) | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_base) / 1048576.0) + " | " +
       printf_text("%.1f", static_cast<double>(p.memory_bytes_planned) / 1048576.0) + " |\n";
  s += "\nThe tiles each memory can be drawn on are pictured in the `.tiles.png` `arpsim plan` writes beside this file: a row for each memory, "
       "fastest at the top, of its faces +X -X +Y -Y +Z -Z, " + std::to_string(kTilePixels) + " pixels a tile; light: can be "
       "drawn on, dark grey: cannot, dark red: a face left out.\n";
  s += "\nMean objects in each planned memory:";
  for (size_t m = 0; m < p.planned.objects.size(); ++m) s += (m ? ", " : " ") + printf_text("%.1f", p.planned.objects[m]);
  s += ".\n\n## The display-memory ladders weighed\n\nHost load over the motion by the run's own priority rule "
       "(host::PriorityScheduler), hardware display memory at the planned face size: as whole faces, and as weighed against "
       "the limit -- where whole faces are over it, each memory holding only the tiles its objects can be drawn on over the "
       "motion where that takes less" + std::string(r.tile_pool && r.weigh_pools ? ", or a tile pool where that takes less still (--weigh-pools)" : "") +
       "; the planned ladder as planned, at its depth code. Renders skipped: the configured engine replayed at every "
       "frame, the planned ladder's with each memory's objects rendered on their own, the others' with the whole scene's "
       "fill (each object's at most what its memory's render fills: those counts are low). Ladders the engine cannot "
       "carry, or over the limit either way, are not listed.\n\n"
       "| memories | update periods, frames | triangles/s | texels filled/s | engine busy, s a second | renders skipped (replayed) | "
       "updated slower than needed | display memory, whole faces, MiB | display memory as weighed, MiB |\n"
       "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  const auto mib = [](int64_t b) { return printf_text("%.1f", static_cast<double>(b) / 1048576.0); };
  for (const LadderLoad& L : p.ladders) {
    const bool planned = ladder_key(L) == ladder_key(p.planned);
    const int64_t whole = planned ? p.memory_bytes_whole : L.memory_bytes_whole;
    const int64_t held = planned ? p.memory_bytes_planned : L.memory_bytes_weighed();
    std::string periods;
    for (int m = 0; m < L.count; ++m) periods += (m ? ", " : "") + std::to_string(dp::update_period_frames(L.update_frames, L.update_ratio, m));
    s += "| " + std::to_string(L.count) + " | " + periods + " | " + printf_text("%.4g", L.triangles_per_s) + " | " +
         printf_text("%.4g", L.texels_per_s) + " | " + printf_text("%.3g", L.engine_busy) + " | " + std::to_string(L.skipped) + " | " +
         printf_text("%.2f %%", 100 * L.late_share) + " | " +
         mib(whole) + " | " + (held < whole ? mib(held) + (!planned && r.tile_pool && r.weigh_pools ? " tile-sparse or pooled" : " tile-sparse") : "whole faces") + (planned ? " (planned)" : "") + " |\n";
  }
  if (!p.regions.empty()) {
    s += "\n## Region priority rendering weighed\n\nWith the planned " + std::to_string(p.planned.count) +
         (p.planned.count == 1 ? " memory" : " memories") + " at the planned theta_t: the scene segmented along square columns "
         "(host::segment_scene), the run's region rule (host::RegionScheduler: a region's objects in the memory of its ring "
         "around the user's region, a memory updated when the user has moved its threshold distance) stepped at every "
         "display frame of the motion as if every memory were free to render; the engine's time for each piece's set-up, "
         "triangles and fill for each eye (its object's measured fill by its share of the triangles); a piece updated slower than its validity at theta_t "
         "needs where its memory's period (the threshold distance walked) is longer. Regions are taken only where they keep "
         "objects within theta_t as well as objects do. By objects: " +
         printf_text("%.4g", p.planned.triangles_per_s) + " triangles/s, " + printf_text("%.2f %%", 100 * p.planned.late_share) +
         " updated slower than needed.\n\n"
         "| region size, m | margin, m | pieces | triangles/s | engine busy, s a second | updated slower than needed | re-assignments | |\n"
         "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const RegionLoad& R : p.regions)
      s += "| " + printf_text("%g", R.size_m) + " | " + printf_text("%g", R.margin_m) + " | " +
           (R.refused.empty() ? std::to_string(R.segments) + " | " + printf_text("%.4g", R.triangles_per_s) + " | " + printf_text("%.3g", R.engine_busy) +
                                    " | " + printf_text("%.2f %%", 100 * R.late_share) + " | " + std::to_string(R.reassignments) + " | " +
                                    (R.size_m == p.config.memory.region_size_m ? "planned" : "")
                              : "| | | | | " + R.refused) +
           " |\n";
  }
  if (p.composition.points > 0) {
    s += "\n## The depth code's composition, by width\n\nThe share of the " + std::to_string(p.composition.composed) +
         " texels where two or more of the planned memories hold a surface that the code composes from a memory whose surface "
         "is not the nearest (" + std::to_string(p.composition.points) + " points of the motion, from the walk's point).\n\n"
         "| bits | composed wrong | share | |\n| --- | --- | --- | --- |\n";
    for (int w = 1; w <= CompositionDepth::kMaxBits; ++w)
      s += "| " + std::to_string(w) + " | " + std::to_string(p.composition.wrong[static_cast<size_t>(w)]) + " | " +
           printf_text("%.3g", p.composition.share(w)) + " | " +
           (w == p.config.memory.depth_bits ? "planned" : w == r.base.memory.depth_bits ? r.base_source : "") + " |\n";
  }
  if (!p.assignment.empty()) {
    s += "\n## Each object's memories over the motion\n\nBy the run's own priority rule at the planned ladder and theta_t, at "
         "every point of the motion (objects of one name together): the fastest and slowest memory it is put in, memory 0 "
         "the fastest. memory.assignment holds them" +
         std::string(p.config.memory.region_size_m > 0 ? " (not used: region priority rendering was taken)" : "") +
         ".\n\n| object | fastest | slowest |\n| --- | --- | --- |\n";
    for (const dp::ObjectAssignment& a : p.assignment) {
      std::string name;  // a '|' would end the cell
      for (const char ch : a.name) name += ch == '|' ? std::string("\\|") : std::string(1, ch);
      s += "| " + name + " | " + std::to_string(a.fastest) + " | " + std::to_string(a.slowest) + " |\n";
    }
  }
  s += "\n## Not decided by this plan\n\n";
  for (const auto& n : p.not_decided) s += "- " + n + "\n";
  return s;
}

}  // namespace arp::sim
