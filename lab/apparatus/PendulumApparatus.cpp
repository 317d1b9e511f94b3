#include "PendulumApparatus.hpp"

#include <algorithm>
#include <cmath>

#include "tracker/SyntheticMotion.hpp"
#include "common/Units.hpp"

namespace arp::apparatus {

namespace {
}

std::vector<tracker::PoseSample> pendulum_motion(const PendulumSpec& p, double seconds, double rate_hz) {
  tracker::SamplingSpec s;
  s.rate_hz = rate_hz;
  s.start_s = p.start_s;
  s.duration_s = seconds;
  return tracker::pendulum({0, 1, 0}, p.amplitude_deg, p.period_s, s);
}

double pendulum_angle_deg(const PendulumSpec& p, double t) {
  return p.amplitude_deg * std::cos(2 * kPi * (t - p.start_s) / p.period_s);
}

std::vector<double> low_point_crossings(const PendulumSpec& p, double t0, double t1) {
  std::vector<double> out;
  // cos is zero a quarter period after the release, then every half period.
  const double first = p.start_s + p.period_s / 4;
  for (double k = std::ceil((t0 - first) / (p.period_s / 2)); first + k * p.period_s / 2 <= t1; k += 1)
    out.push_back(first + k * p.period_s / 2);
  return out;
}

ChannelEvents observe(lab::DisplayArchitecture& a, const lab::DisplayRaster& d, const lab::TrackerFeed& feed,
                      lab::Prediction pred, int64_t first_frame, int64_t frames) {
  ChannelEvents ev;
  ev.name = a.name();
  a.schedule(first_frame, first_frame + frames - 1);
  const int cx = d.width() / 2, cy = d.height() / 2;
  bool have = false, last = false;
  for (int64_t f = first_frame; f < first_frame + frames; ++f) {
    const lab::PoseUse u = a.pose_for(f, cx, cy);
    if (!u.shown) continue;
    glm::dquat q = feed.orientation_for(u.compute_ps, u.target_ps, pred);
    if (u.blend > 0) q = glm::slerp(q, feed.orientation_for(u.compute2_ps, u.target2_ps, pred), u.blend);
    // The world left of the low-point direction (x < 0) is light.
    const bool light = (q * d.ray(cx, cy)).x < 0;
    ev.refreshes.push_back({d.photon_ps(f, cx, cy), light, u.compute_ps, feed.report_sample_ps(u.compute_ps)});
    if (have && light != last) ev.render_starts.push_back(u.compute_ps);
    have = true;
    last = light;
  }
  std::sort(ev.render_starts.begin(), ev.render_starts.end());
  return ev;
}

ChannelMeasurement analyse(const PendulumSpec& p, const ScopeEdges& e, size_t ch, const ChannelEvents& ev) {
  ChannelMeasurement m;
  m.name = ev.name;
  const auto& renders = e.render_rise[ch];
  const auto& screens = e.screen_edge[ch];
  double sum_t = 0, sum_r = 0, sum_e = 0, sum_i = 0;
  for (size_t i = 0; i < e.pendulum_rise.size() && i < e.pendulum_fall.size(); ++i) {
    const int64_t mid = (e.pendulum_rise[i] + e.pendulum_fall[i]) / 2;
    const auto r = std::lower_bound(renders.begin(), renders.end(), mid);
    if (r == renders.end()) break;
    const auto s = std::lower_bound(screens.begin(), screens.end(), *r);
    if (s == screens.end()) break;
    Passage ps;
    ps.pendulum_mid_s = static_cast<double>(mid) * 1e-12;
    ps.render_start_s = static_cast<double>(*r) * 1e-12;
    ps.screen_s = static_cast<double>(*s) * 1e-12;
    const auto cross = low_point_crossings(p, ps.pendulum_mid_s - p.period_s / 4, ps.pendulum_mid_s + p.period_s / 4);
    if (cross.empty()) continue;
    ps.crossing_s = *std::min_element(cross.begin(), cross.end(), [&](double a, double b) {
      return std::abs(a - ps.pendulum_mid_s) < std::abs(b - ps.pendulum_mid_s);
    });
    ps.tracking_ms = (ps.render_start_s - ps.pendulum_mid_s) * 1e3;
    ps.rendering_ms = (ps.screen_s - ps.render_start_s) * 1e3;
    ps.external_total_ms = (ps.screen_s - ps.pendulum_mid_s) * 1e3;
    // The refresh that made the edge: the first photon at or after the edge's sample minus one sample.
    const int64_t edge = *s;
    const auto it = std::lower_bound(ev.refreshes.begin(), ev.refreshes.end(), edge - static_cast<int64_t>(std::llround(p.scope_sample_s * 1e12)),
                                     [](const ChannelEvents::Refresh& a, int64_t t) { return a.photon_ps < t; });
    if (it == ev.refreshes.end()) continue;
    ps.internal_total_ms = (static_cast<double>(it->photon_ps) * 1e-12 - ps.crossing_s) * 1e3;
    ps.internal_report_ms = static_cast<double>(it->photon_ps - it->report_ps) * 1e-9;
    ps.internal_render_ms = static_cast<double>(it->photon_ps - it->compute_ps) * 1e-9;
    m.max_disagreement_ms = std::max(m.max_disagreement_ms, std::abs(ps.external_total_ms - ps.internal_total_ms));
    sum_t += ps.tracking_ms;
    sum_r += ps.rendering_ms;
    sum_e += ps.external_total_ms;
    sum_i += ps.internal_total_ms;
    m.passages.push_back(ps);
  }
  if (!m.passages.empty()) {
    const double n = static_cast<double>(m.passages.size());
    m.mean_tracking_ms = sum_t / n;
    m.mean_rendering_ms = sum_r / n;
    m.mean_external_ms = sum_e / n;
    m.mean_internal_ms = sum_i / n;
  }
  return m;
}

}  // namespace arp::apparatus
