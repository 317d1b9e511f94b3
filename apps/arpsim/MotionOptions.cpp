#include "MotionOptions.hpp"

#include <cmath>
#include <sstream>

#include "common/InputError.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::app {

namespace {
glm::dvec3 parse_axis(const std::string& s) {
  std::stringstream ss(s);
  glm::dvec3 v(0.0);
  char c1 = 0, c2 = 0;
  if (!(ss >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !ss.eof())
    throw InputError("--axis", "", "expected three comma-separated numbers x,y,z");
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || glm::length(v) == 0.0)
    throw InputError("--axis", "", "the rotation axis must be finite and non-zero");
  return v;
}
}  // namespace

void MotionOptions::add_to(CLI::App& cmd, bool required) {
  auto* m = cmd.add_option("--motion", motion, "Synthetic motion: rotate (constant rate), shake (sinusoid), pendulum")
                ->check(CLI::IsMember({"rotate", "shake", "pendulum"}));
  if (required) m->required();
  cmd.add_option("--axis", axis, "Rotation axis in the head frame, x,y,z (0,1,0: yaw)")->capture_default_str();
  cmd.add_option("--rate", rate, "rotate: degrees per second")->capture_default_str();
  cmd.add_option("--peak", peak, "shake: peak angular velocity, degrees per second")->capture_default_str();
  cmd.add_option("--frequency", frequency, "shake: Hz")->capture_default_str();
  cmd.add_option("--amplitude", amplitude, "pendulum: degrees")->capture_default_str();
  cmd.add_option("--period", period, "pendulum: seconds")->capture_default_str();
  cmd.add_option("--hz", hz, "Tracker sample rate")->capture_default_str();
  cmd.add_option("--noise", noise, "Random extra rotation per sample, degrees (standard deviation)")->capture_default_str();
  cmd.add_option("--seed", seed, "Noise seed")->capture_default_str();
}

std::vector<tracker::PoseSample> MotionOptions::make(double start_s, double seconds) const {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) throw InputError("--seconds", "", "must be a positive number");
  if (!(hz > 0.0) || !std::isfinite(hz)) throw InputError("--hz", "", "must be a positive number");
  if (seconds * hz > 1e8) throw InputError("--seconds", "", "more than 1e8 samples; lower --seconds or --hz");
  if (!(noise >= 0.0) || !std::isfinite(noise)) throw InputError("--noise", "", "must be >= 0 degrees");
  if (!std::isfinite(start_s) || std::abs(start_s) > 9e6) throw InputError("--start", "", "must be within +-9e6 s");
  tracker::SamplingSpec s;
  s.rate_hz = hz;
  s.duration_s = seconds;
  s.start_s = start_s;
  s.noise_deg = noise;
  s.seed = seed;
  const glm::dvec3 ax = parse_axis(axis);
  if (motion == "rotate") {
    if (!std::isfinite(rate)) throw InputError("--rate", "", "must be finite");
    return tracker::constant_rotation(ax, rate, s);
  }
  if (motion == "shake") {
    if (!(frequency > 0.0) || !std::isfinite(frequency)) throw InputError("--frequency", "", "must be positive");
    if (!std::isfinite(peak)) throw InputError("--peak", "", "must be finite");
    return tracker::head_shake(ax, peak, frequency, s);
  }
  if (!(period > 0.0) || !std::isfinite(period)) throw InputError("--period", "", "must be positive");
  if (!std::isfinite(amplitude)) throw InputError("--amplitude", "", "must be finite");
  return tracker::pendulum(ax, amplitude, period, s);
}

}  // namespace arp::app
