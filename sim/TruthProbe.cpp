#include "sim/TruthProbe.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numeric>
#include <optional>
#include <string_view>

#include "sim/FrameImage.hpp"
#include "common/InputError.hpp"
#include "common/ParameterJson.hpp"
#include "host/cubemap/ImageFiles.hpp"
#include "host/error/FrameError.hpp"
#include "host/error/SeamMetrics.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "common/Units.hpp"
#include "common/WholeNumber.hpp"

namespace arp::sim {

namespace {

constexpr uint8_t kTearMarks = host::kCrackMark;  // the seam's own discontinuity picks the place

double mean_of(const std::vector<int64_t>& v) {
  return v.empty() ? 0.0 : static_cast<double>(std::accumulate(v.begin(), v.end(), int64_t{0})) / static_cast<double>(v.size());
}

// The truth: one memory holding everything. At the run's own face size (0) it reads as the run does; at a
// face size asked for, it is one reference for runs of any configuration: the built-in datapath widths,
// texel format and all six faces at that size (its range checked as the key's, the error naming the
// option), with the run's display, lens and pipeline (they define the pixels and their filter).
dp::ArpConfig truth_config(const dp::ArpConfig& run, int face_size) {
  dp::ArpConfig c = run;
  c.memory.count = 1;
  c.memory.tiles.clear();  // it holds every tile: a reference, not the run's tile-sparse hardware
  c.memory.tile_pool.clear();
  c.memory.assignment.clear();  // one memory: nothing to place
  if (face_size == 0) return c;
  const dp::ArpConfig builtin;
  c.widths = builtin.widths;
  c.memory.red_bits = builtin.memory.red_bits;
  c.memory.green_bits = builtin.memory.green_bits;
  c.memory.blue_bits = builtin.memory.blue_bits;
  c.memory.depth_bits = builtin.memory.depth_bits;
  c.memory.faces = builtin.memory.faces;
  set_parameter(*dp::arp_parameters().find("memory.face_size"), nlohmann::json(face_size), "--truth-face-size", c);
  return c;
}

}  // namespace

dp::ArpConfig truth_image_config(const dp::ArpConfig& truth, int n) {
  dp::ArpConfig c = truth;
  dp::VideoTimingConfig& t = c.timing;
  for (int* v : {&t.h_active, &t.h_front_porch, &t.h_sync, &t.h_back_porch, &t.v_active, &t.v_front_porch, &t.v_sync,
                 &t.v_back_porch})
    *v *= n;
  t.pixel_clock_hz *= int64_t{n} * n;
  c.lens.center_offset_px *= n;
  return c;
}

TearAt parse_tear_at(const std::string& text, int64_t first_frame, int64_t frames, int64_t every, const dp::VideoTimingConfig& t) {
  // Four whole numbers, each read whole and compared as int64 (a coordinate near INT_MAX wrapped past the
  // bounds check below, and the window was drawn outside the image).
  std::optional<int64_t> v[4];
  size_t from = 0;
  for (int i = 0; i < 4; ++i) {
    const size_t colon = i < 3 ? text.find(':', from) : text.size();
    if (colon == std::string::npos) break;
    v[i] = whole_number(std::string_view(text).substr(from, colon - from));
    from = colon + 1;
  }
  if (std::any_of(std::begin(v), std::end(v), [](const std::optional<int64_t>& x) { return !x || *x < 0; }))
    throw InputError("--tear-at", text, "expected FRAME:EYE:X:Y, non-negative whole numbers");
  // (first_frame >= 0, so the difference cannot overflow)
  if (every <= 0 || first_frame < 0 || *v[0] < first_frame || *v[0] - first_frame >= frames || (*v[0] - first_frame) % every != 0)
    throw InputError("--tear-at", text, "the frame must be one this run measures (--first-frame + k * --error-every)");
  if (*v[1] >= t.eyes || *v[2] > t.h_active - TruthProbe::kTearWindowW || *v[3] > t.v_active - TruthProbe::kTearWindowH)
    throw InputError("--tear-at", text,
                     "the " + std::to_string(TruthProbe::kTearWindowW) + "x" + std::to_string(TruthProbe::kTearWindowH) + " window must lie inside one eye's image");
  return {*v[0], static_cast<int>(*v[1]), static_cast<int>(*v[2]), static_cast<int>(*v[3])};
}

TruthProbe::TruthProbe(const TruthProbeSetup& s)
    : s_(s),
      truth_cfg_(truth_config(*s.config, s.truth_face_size)),
      truth_image_cfg_(truth_image_config(truth_cfg_, s.supersample)),
      timing_(s.config->timing),
      lens_(s.config->lens, s.config->timing, s.config->widths.vec_frac),
      rot_(s.config->widths),
      addr_(s.config->widths, s.config->memory.face_size),
      own_truth_(s.truth_face_size == 0),
      truth_rot_(truth_cfg_.widths),
      truth_addr_(truth_cfg_.widths, truth_cfg_.memory.face_size),
      latch_(*s.config),
      px_rad_(s.config->lens.fov_deg * kPi / 180.0 / s.config->timing.h_active),
      truth_ids_(static_cast<size_t>(s.config->timing.eyes)) {
  const dp::ArpConfig& c = *s.config;
  if (!s.tear_at.empty()) tear_at_ = parse_tear_at(s.tear_at, s.first_frame, s.frames, s.every, c.timing);
  if (!own_truth_) truth_lens_.emplace(truth_cfg_.lens, truth_cfg_.timing, truth_cfg_.widths.vec_frac);
  truth_mem_ = std::make_unique<dp::DisplayMemorySet>(truth_cfg_.memory, c.timing.eyes);
  truth_model_ = std::make_unique<FunctionalModel>(truth_image_cfg_);
}

TruthProbe::~TruthProbe() = default;

void TruthProbe::measure(const HmdFrame& f, int64_t frame, nlohmann::json& out) {
  const dp::ArpConfig& c = *s_.config;
  const dp::OrientationStream& stream = *s_.orientation;
  const dp::DisplayMemorySet& mem = *s_.memories;
  const host::HostSimulation& hostsim = *s_.host;
  const host::Scene& scene = *s_.scene;
  const dp::VideoTiming& t = timing_;
  const double tm = static_cast<double>(t.cycles_to_ps(t.frame_start_cycle(frame) + t.frame_cycles() / 2)) * 1e-12;
  const dp::Quat& hq = stream[stream.index_at(static_cast<int64_t>(std::llround(tm * 1e12)))].q;
  const glm::dquat q(hq.w, hq.x, hq.y, hq.z);
  host::CubeFaceRenderer renderer;
  renderer.set_threads(s_.threads);
  for (int e = 0; e < c.timing.eyes; ++e) {
    renderer.render(scene, {}, tm, host::eye_position(s_.walk->position(tm), q, e, c.timing.eyes, s_.ipd_m), truth_mem_->bank(e, 0),
                    &truth_ids_[static_cast<size_t>(e)]);
    truth_mem_->bank(e, 0).vblank();
  }
  HmdFrame truth;
  RenderOptions tro;
  tro.threads = s_.threads;
  truth_model_->render(*truth_mem_, stream, frame, truth, tro);
  if (s_.supersample > 1) truth = host::area_mean(truth, s_.supersample);
  const host::ImageError ie = host::image_error(f, truth);
  // Tracked points: each object's centre, where its memory's image shows it against where it is.
  const glm::dvec3 eye_now = host::eye_position(s_.walk->position(tm), q, 0, c.timing.eyes, s_.ipd_m);
  const glm::dvec3 ahead = q * glm::dvec3(0, 0, -1);
  double max_px = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& o = scene.objects[i];
    const int m = hostsim.shown_in(i);
    if (m < 0) continue;
    const double then = hostsim.rendered_at(m);
    if (!std::isfinite(then)) continue;
    const glm::dvec3 now_p = o.world_bound(tm).center;
    if (glm::dot(glm::normalize(now_p - eye_now), ahead) < std::cos(c.lens.fov_deg * 0.6 * kPi / 180.0)) continue;  // outside the view
    const double d = host::displacement_rad(hostsim.rendered_from(m, 0), o.world_bound(then).center, eye_now, now_p);
    max_px = std::max(max_px, d / px_rad_);
    worst_rad_ = std::max(worst_rad_, d);
  }
  // Which object each pixel shows (the nearest texel the pipeline addresses,
  // composited by depth across the memories) against the truth's.
  int64_t differ = 0, total = 0;
  const uint32_t empty = mem.format().empty_depth();
  const int W = c.timing.h_active, H = c.timing.v_active;
  host::ObjectMap shown_map, truth_map;
  shown_map.resize(W, H, c.timing.eyes);
  truth_map.resize(W, H, c.timing.eyes);
  for (int e = 0; e < c.timing.eyes; ++e)
    for (int y = 0; y < H; ++y) {
      size_t held = SIZE_MAX;
      dp::Mat3q M{}, Mt{};
      for (int x = 0; x < W; ++x) {
        const size_t sidx = latch_.sample(stream, frame, e, x, y);
        if (sidx != held) {
          M = dp::quantise_rotation(stream[sidx].q, c.widths.mat_frac);
          Mt = dp::quantise_rotation(stream[sidx].q, truth_cfg_.widths.mat_frac);
          held = sidx;
        }
        const dp::CubeAddress ad = dp::generate_address(dp::rotate(M, lens_.at(e, x, y), rot_), addr_);
        // The truth's texel for this pixel, by the truth's own arithmetic (its widths may differ).
        const dp::CubeAddress at = own_truth_ ? ad : dp::generate_address(dp::rotate(Mt, truth_lens_->at(e, x, y), truth_rot_), truth_addr_);
        uint32_t best_depth = empty, shown = 0;
        for (int m = 0; m < mem.count(); ++m) {
          const uint32_t dpt = dp::texel_depth(mem.bank(e, m).read(ad.face, ad.x, ad.y));
          if (dpt < best_depth) {
            best_depth = dpt;
            shown = hostsim.shown_object(m, e, ad.face, ad.x, ad.y);
          }
        }
        const auto& tf = truth_ids_[static_cast<size_t>(e)][at.face];
        const uint32_t truth_object =
            tf.object.empty() ? 0u : tf.object[static_cast<size_t>(at.y) * static_cast<size_t>(tf.size) + static_cast<size_t>(at.x)];
        differ += shown != truth_object;
        ++total;
        shown_map.id[shown_map.index(e, x, y)] = shown;
        truth_map.id[truth_map.index(e, x, y)] = truth_object;
      }
    }
  const double object_share = total ? static_cast<double>(differ) / static_cast<double>(total) : 0.0;
  worst_object_share_ = std::max(worst_object_share_, object_share);
  // Tearing and cracks along the seams of cut objects.
  int64_t tear = 0, gap = 0, crack = 0;
  if (s_.segmented && !s_.segmented->source.empty()) {
    host::SeamPieces pieces;
    pieces.source = s_.segmented->source;
    pieces.memory.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) pieces.memory[i] = hostsim.shown_in(i);
    const host::SeamMeasure sm = host::measure_seams(shown_map, truth_map, pieces);
    tear = sm.tear_pixels;
    gap = sm.gap_pixels;
    crack = sm.crack_pixels;
    if (!s_.tear_image.empty()) {
      host::TearWindow w;
      if (tear_at_.frame >= 0) {
        if (frame == tear_at_.frame) {
          w = {tear_at_.eye, tear_at_.x, tear_at_.y, kTearWindowW, kTearWindowH, 0};
          for (int y = 0; y < w.height; ++y)
            for (int x = 0; x < w.width; ++x) w.marked += (sm.marks[shown_map.index(w.eye, w.x + x, w.y + y)] & kTearMarks) ? 1 : 0;
        }
      } else {
        w = host::densest_window(shown_map, sm.marks, kTearMarks, kTearWindowW, kTearWindowH);
      }
      if (w.width > 0 && (tear_at_.frame >= 0 || w.marked > tear_best_.marked || tear_picture_.width == 0)) {
        tear_best_ = w;
        tear_frame_ = frame;
        tear_picture_ = host::magnified_tear(frame_to_image(f), frame_to_image(truth), shown_map, sm.marks, w, kTearScale);
      }
    }
  }
  tears_.push_back(tear);
  cracks_.push_back(crack);
  gaps_.push_back(gap);
  out["error"] = {{"psnr_db", std::isfinite(ie.psnr_db) ? ie.psnr_db : 999.0},
                  {"pixels_showing_another_object", object_share},
                  {"tear_pixels", tear},
                  {"tear_gap_pixels", gap},
                  {"crack_pixels", crack},
                  {"mse", ie.mse},
                  {"pixels_differing", ie.differing},
                  {"max_displacement_px", max_px}};
  psnrs_.push_back(ie.psnr_db);  // infinite when identical
}

nlohmann::json TruthProbe::summary() const {
  // Over the frames that differ from the truth: an identical frame's PSNR is
  // infinite, and averaging in a stand-in for it (999 dB, as a frame's row
  // says) made the mean meaningless whenever some frames were exact.
  double mean = 0, worst = 999.0;
  int64_t differing = 0;
  for (double p : psnrs_)
    if (std::isfinite(p)) {
      mean += p;
      worst = std::min(worst, p);
      ++differing;
    }
  return {{"frames_measured", psnrs_.size()},
          {"truth_face_size", truth_cfg_.memory.face_size},
          {"truth_supersample", s_.supersample},
          {"frames_identical_to_truth", static_cast<int64_t>(psnrs_.size()) - differing},
          {"mean_psnr_db", psnrs_.empty() ? 0.0 : differing ? mean / static_cast<double>(differing) : 999.0},
          {"worst_psnr_db", psnrs_.empty() ? 0.0 : worst},
          {"max_displacement_px", worst_rad_ / px_rad_},
          {"max_displacement_deg", rad_to_deg(worst_rad_)},  // against theta_t: priority rendering's bound
          {"worst_share_showing_another_object", worst_object_share_},
          {"mean_tear_pixels", mean_of(tears_)},
          {"max_tear_pixels", tears_.empty() ? 0 : *std::max_element(tears_.begin(), tears_.end())},
          {"mean_crack_pixels", mean_of(cracks_)},
          {"tear_image", s_.tear_image.empty() ? nlohmann::json()
                                               : nlohmann::json{{"file", s_.tear_image}, {"frame", tear_frame_}, {"eye", tear_best_.eye},
                                                                {"x", tear_best_.x}, {"y", tear_best_.y}, {"width", tear_best_.width},
                                                                {"height", tear_best_.height}, {"crack_pixels", tear_best_.marked},
                                                                {"scale", kTearScale}}},
          {"mean_tear_gap_pixels", mean_of(gaps_)}};
}

std::string TruthProbe::write_tear_image() const {
  if (tear_picture_.width == 0) throw InputError("--tear-image", s_.tear_image, "no measured frame had a seam to show");
  host::write_rgb8(s_.tear_image, tear_picture_);
  char line[512];
  std::snprintf(line, sizeof line,
                "  magnified tear: %s (frame %" PRId64 ", eye %d, x %d, y %d, %" PRId64 " crack pixels; --tear-at %" PRId64
                ":%d:%d:%d shows the same place)\n",
                s_.tear_image.c_str(), tear_frame_, tear_best_.eye, tear_best_.x, tear_best_.y, tear_best_.marked, tear_frame_, tear_best_.eye,
                tear_best_.x, tear_best_.y);
  return line;
}

}  // namespace arp::sim
