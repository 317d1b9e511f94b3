#include "LatencyLab.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace arp::lab {

Distribution distribution(std::vector<double> v) {
  Distribution d;
  if (v.empty()) return d;
  std::sort(v.begin(), v.end());
  auto q = [&](double p) { return v[std::min(v.size() - 1, static_cast<size_t>(std::floor(p * static_cast<double>(v.size() - 1) + 0.5)))]; };
  d.min = v.front();
  d.max = v.back();
  d.p50 = q(0.5);
  d.p99 = q(0.99);
  d.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  d.count = static_cast<int64_t>(v.size());
  return d;
}

double pixel_error_deg(const DisplayRaster& d, const TrackerFeed& feed, const PoseUse& u, Prediction p, int64_t photon_ps, int x,
                       int y, double point_distance_m) {
  glm::dquat used = feed.orientation_for(u.compute_ps, u.target_ps, p);
  if (u.blend > 0) used = glm::slerp(used, feed.orientation_for(u.compute2_ps, u.target2_ps, p), u.blend);
  const glm::dvec3 r = d.ray(x, y);
  // The world point drawn at (x, y) -- point_distance_m away from where the
  // image was drawn from -- and the direction the true head at photon time sees it.
  glm::dvec3 world = used * r;
  if (feed.has_positions()) {
    const glm::dvec3 from = feed.truth_position(u.position_ps >= 0 ? u.position_ps : feed.report_sample_ps(u.compute_ps));
    world = from + point_distance_m * world - feed.truth_position(photon_ps);
  }
  const glm::dvec3 seen = glm::conjugate(feed.truth(photon_ps)) * world;
  const glm::dvec3 n = glm::normalize(seen);
  return glm::degrees(std::atan2(glm::length(glm::cross(n, r)), glm::dot(n, r)));  // exact near zero, unlike acos
}

ArchitectureResult measure(DisplayArchitecture& a, const DisplayRaster& d, const TrackerFeed& feed, const LabSettings& s) {
  ArchitectureResult r;
  r.name = a.name();
  a.schedule(s.first_frame, s.first_frame + s.frames - 1);
  r.description = a.description();  // after scheduling: it may report what the schedule did
  const int W = d.width(), H = d.height(), cx = W / 2, cy = H / 2;
  std::vector<int> xs, ys;
  for (int x = 0; x < W; x += s.grid_step) xs.push_back(x);
  if (xs.back() != W - 1) xs.push_back(W - 1);
  for (int y = 0; y < H; y += s.grid_step) ys.push_back(y);
  if (ys.back() != H - 1) ys.push_back(H - 1);
  const double ppd = d.pixels_per_degree();
  std::vector<double> centre, worst, position_age;
  for (int64_t f = s.first_frame; f < s.first_frame + s.frames; ++f) {
    FramePoint fp;
    const int64_t tc = d.photon_ps(f, cx, cy);
    fp.time_s = static_cast<double>(tc) * 1e-12;
    const PoseUse uc = a.pose_for(f, cx, cy);
    fp.shown = uc.shown;
    if (!uc.shown) {
      ++r.frames_without_image;
      r.frames.push_back(fp);
      continue;
    }
    fp.centre_error_px = pixel_error_deg(d, feed, uc, s.prediction, tc, cx, cy, s.point_distance_m) * ppd;
    fp.centre_latency_ms = static_cast<double>(tc - feed.report_sample_ps(uc.compute_ps)) * 1e-9;
    double sum = 0;
    int64_t n = 0;
    for (int y : ys)
      for (int x : xs) {
        const PoseUse u = a.pose_for(f, x, y);
        if (!u.shown) continue;
        const int64_t t = d.photon_ps(f, x, y);
        const double e = pixel_error_deg(d, feed, u, s.prediction, t, x, y, s.point_distance_m) * ppd;
        fp.max_error_px = std::max(fp.max_error_px, e);
        sum += e;
        ++n;
        r.latency_ms.push_back(static_cast<double>(t - feed.report_sample_ps(u.compute_ps)) * 1e-9);
        if (feed.has_positions())
          position_age.push_back(static_cast<double>(t - (u.position_ps >= 0 ? u.position_ps : feed.report_sample_ps(u.compute_ps))) * 1e-9);
      }
    fp.mean_error_px = n ? sum / static_cast<double>(n) : 0.0;
    centre.push_back(fp.centre_error_px);
    worst.push_back(fp.max_error_px);
    r.frames.push_back(fp);
  }
  r.latency = distribution(r.latency_ms);
  r.position_age_ms = distribution(position_age);
  r.centre_error = distribution(centre);
  r.max_error = distribution(worst);
  r.missed_images = a.missed_images();
  r.image_interval_s = a.image_interval_s();
  return r;
}

}  // namespace arp::lab
