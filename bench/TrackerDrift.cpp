// Fusion drift and prediction error on seeded synthetic data, and prediction
// error on recorded trace files: the figures in docs/tracker.md.
// Usage: arp_tracker_drift [SECONDS [TRACE.csv ...]]   (default 60 s, no traces)
// A trace carries no angular velocity: it is estimated from consecutive
// samples, as a system predicting from a tracker's reports would.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "tracker/DriftScenario.hpp"
#include "tracker/Fusion.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/TraceFile.hpp"

namespace {

// The orientation of a trace at time t (slerp between samples, held outside).
glm::dquat at(const std::vector<arp::tracker::PoseSample>& tr, int64_t t) {
  if (t <= tr.front().time_ps) return tr.front().orientation;
  if (t >= tr.back().time_ps) return tr.back().orientation;
  const auto it = std::upper_bound(tr.begin(), tr.end(), t, [](int64_t v, const arp::tracker::PoseSample& s) { return v < s.time_ps; });
  const auto& b = *it;
  const auto& a = *(it - 1);
  return glm::slerp(a.orientation, b.orientation, static_cast<double>(t - a.time_ps) / static_cast<double>(b.time_ps - a.time_ps));
}

void trace_prediction(const char* path) {
  using namespace arp::tracker;
  const auto tr = read_trace_csv(path);
  std::printf("\nConstant-angular-velocity prediction on %s (%zu samples, %.1f s; rate from consecutive samples):\n\n", path,
              tr.size(), static_cast<double>(tr.back().time_ps - tr.front().time_ps) * 1e-12);
  std::printf("| horizon (ms) | mean error (deg) | max error (deg) | without prediction: mean (deg) |\n| --- | --- | --- | --- |\n");
  for (int h : {0, 5, 10, 20, 33, 50, 100}) {
    const int64_t hp = static_cast<int64_t>(h) * 1'000'000'000;
    double mean = 0, worst = 0, hold = 0;
    size_t n = 0;
    for (size_t i = 1; i < tr.size() && tr[i].time_ps + hp <= tr.back().time_ps; ++i, ++n) {
      const double dt = static_cast<double>(tr[i].time_ps - tr[i - 1].time_ps) * 1e-12;
      const glm::dvec3 w = rate_between(tr[i - 1].orientation, tr[i].orientation, dt);
      const glm::dquat truth = at(tr, tr[i].time_ps + hp);
      const double e = angle_between_deg(predict(tr[i].orientation, w, h * 1e-3), truth);
      mean += e;
      worst = std::max(worst, e);
      hold += angle_between_deg(tr[i].orientation, truth);
    }
    if (n == 0) break;
    std::printf("| %d | %.4f | %.4f | %.4f |\n", h, mean / static_cast<double>(n), worst, hold / static_cast<double>(n));
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace arp::tracker;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 60.0;
  if (!(seconds > 0.0)) {
    std::fprintf(stderr, "usage: %s [SECONDS > 0]\n", argv[0]);
    return 2;
  }
  std::printf("Fusion drift over %.0f s (bursts of 150 deg/s shaking, 3 s still; gyro bias 0.5/-0.3/0.4 deg/s,\n"
              "noise 0.01 rad/s, accel noise 0.05 m/s^2, 1 kHz, seed 7):\n\n", seconds);
  std::printf("| fusion | error at end (deg) | drift (deg/min) | tilt error (deg) | bias error (deg/s) |\n");
  std::printf("| --- | --- | --- | --- | --- |\n");
  const struct { const char* name; bool tilt, bias; } modes[] = {
      {"gyro integration only", false, false}, {"+ tilt correction", true, false}, {"+ tilt correction + bias estimation", true, true}};
  for (const auto& m : modes) {
    FusionParams p;
    p.correct_tilt = m.tilt;
    p.estimate_bias = m.bias;
    const DriftResult r = run_drift(p, seconds);
    std::printf("| %s | %.3f | %.3f | %.3f | %.4f |\n", m.name, r.total_deg, r.total_deg * 60.0 / seconds, r.tilt_deg,
                r.bias_error_deg_s);
  }
  // The bias model's trade (tracker/Fusion.hpp): a slower bias filter eats less of a slow turn but
  // leaves more drift before it has learned the bias.
  std::printf("\nBias time constant: what a slow turn loses against the drift left (defaults otherwise; 1 kHz, seed 7).\n"
              "Turns: level head, about the vertical, 10 s, IMU noise and no bias. Drift: the scenario above.\n"
              "Bias learnt: a still head, bias 0.5 deg/s on each axis (0.87 deg/s), error left after 2, 6 and 10 min.\n\n");
  std::printf("| bias time constant (s) | turn 0.5 deg/s: error (deg) | 1 deg/s | 3 deg/s | drift 60 s: error (deg) | drift 600 s | "
              "bias error after 2 min | 6 min | 10 min |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (double tau : {2.0, 10.0, 30.0, 60.0, 120.0, 300.0}) {
    FusionParams p;
    p.bias_time_constant = tau;
    const glm::dvec3 bias = glm::radians(glm::dvec3(0.5));
    std::printf("| %.0f%s | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f %% | %.1f %% | %.1f %% |\n", tau,
                tau == FusionParams{}.bias_time_constant ? " (default)" : "", run_slow_turn(p, 0.5, 10), run_slow_turn(p, 1, 10),
                run_slow_turn(p, 3, 10), run_drift(p, 60).total_deg, run_drift(p, 600).total_deg, 100 * run_bias_learning(p, bias, 120),
                100 * run_bias_learning(p, bias, 360), 100 * run_bias_learning(p, bias, 600));
  }
  std::printf("\nThe default fusion over an hour of the drift scenario (streamed, constant memory):\n\n"
              "| after (min) | error (deg) | tilt error (deg) | bias error (deg/s) |\n| --- | --- | --- | --- |\n");
  for (double minutes : {1.0, 10.0, 30.0, 60.0}) {
    const DriftResult r = run_drift(FusionParams{}, minutes * 60.0);
    std::printf("| %.0f | %.3f | %.3f | %.4f |\n", minutes, r.total_deg, r.tilt_deg, r.bias_error_deg_s);
  }
  // The same hour with the magnetometer's yaw correction (tracker/Fusion.hpp: yaw_gain), for a few gains:
  // the error settles near what is left of the bias about the vertical over the gain.
  std::printf("\nThe same hour with the magnetometer (2 milligauss of noise), per yaw gain:\n\n"
              "| yaw gain (1/s) | after 1 min: error (deg) | 10 min | 30 min | 60 min | tilt at 60 min (deg) |\n"
              "| --- | --- | --- | --- | --- | --- |\n");
  for (double gain : {0.0, 0.02, 0.1, 0.5}) {
    FusionParams p;
    p.yaw_gain = gain;
    double e[4] = {0, 0, 0, 0}, tilt = 0;
    const double minutes[4] = {1, 10, 30, 60};
    for (int i = 0; i < 4; ++i) {
      const DriftResult r = run_drift(p, minutes[i] * 60.0);
      e[i] = r.total_deg;
      tilt = r.tilt_deg;
    }
    std::printf("| %g%s | %.3f | %.3f | %.3f | %.3f | %.3f |\n", gain, gain == 0 ? " (no magnetometer)" : "", e[0], e[1], e[2], e[3], tilt);
  }
  std::printf("\nConstant-angular-velocity prediction on a 1 Hz head shake (truth, 1 kHz samples):\n\n");
  std::printf("| horizon (ms) | 200 deg/s peak: mean / max error (deg) | 370 deg/s peak: mean / max error (deg) |\n");
  std::printf("| --- | --- | --- |\n");
  SamplingSpec s;
  s.duration_s = 3.0;
  const auto slow = head_shake(glm::dvec3(0, 1, 0), 200.0, 1.0, s), fast = head_shake(glm::dvec3(0, 1, 0), 370.0, 1.0, s);
  for (int h : {0, 5, 10, 20, 33, 50, 100}) {
    double mean[2] = {0, 0}, worst[2] = {0, 0};
    const std::vector<PoseSample>* traces[2] = {&slow, &fast};
    for (int k = 0; k < 2; ++k) {
      const auto& tr = *traces[k];
      size_t n = 0;
      for (size_t i = 0; i + static_cast<size_t>(h) < tr.size(); ++i, ++n) {
        const double e = angle_between_deg(predict(tr[i].orientation, tr[i].angular_velocity, h * 1e-3),
                                           tr[i + static_cast<size_t>(h)].orientation);
        mean[k] += e;
        worst[k] = std::max(worst[k], e);
      }
      mean[k] /= static_cast<double>(n);
    }
    std::printf("| %d | %.4f / %.4f | %.4f / %.4f |\n", h, mean[0], worst[0], mean[1], worst[1]);
  }
  for (int i = 2; i < argc; ++i) {
    try {
      trace_prediction(argv[i]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "arp_tracker_drift: %s\n", e.what());
      return 2;
    }
  }
  return 0;
}
