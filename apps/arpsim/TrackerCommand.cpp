// arpsim tracker: head-tracker input. `list` finds Oculus Rift DK1/DK2
// trackers on USB; `synth` writes a synthetic head-motion trace (CSV).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "Commands.hpp"
#include "common/InputError.hpp"
#include "tracker/SyntheticMotion.hpp"
#include "tracker/TraceFile.hpp"
#include "tracker/UsbTrackers.hpp"

namespace arp::app {

namespace {

int run_list() {
  const tracker::UsbScan scan = tracker::scan_usb_trackers();
  if (!scan.usb_available) {
    std::printf("arpsim tracker list: USB is not available here (%s).\n", scan.usb_error.c_str());
    return 1;
  }
  if (scan.trackers.empty()) {
    std::printf("arpsim tracker list: no Oculus Rift DK1/DK2 found (vendor 0x2833, products 0x0001/0x0021); "
                "%d USB device%s visible.\n",
                scan.devices_seen, scan.devices_seen == 1 ? "" : "s");
    return 0;
  }
  for (const auto& t : scan.trackers)
    std::printf("%s  bus %03d address %03d  %s\n", t.model == tracker::RiftModel::DK1 ? "Oculus Rift DK1" : "Oculus Rift DK2",
                t.bus, t.address, t.can_open ? "ready" : t.problem.c_str());
  return 0;
}

struct SynthArgs {
  std::string motion, axis = "0,1,0", out;
  double rate = 100.0, peak = 200.0, frequency = 1.0, amplitude = 30.0, period = 2.0;
  double seconds = 10.0, hz = 1000.0, noise = 0.0, start = 0.0;
  uint64_t seed = 1;
};

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

int run_synth(const SynthArgs& a) {
  for (auto [name, v] : {std::pair<const char*, double>{"--seconds", a.seconds}, {"--hz", a.hz}}) {
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(name, "", "must be a positive number");
  }
  if (a.seconds * a.hz > 1e8) throw InputError("--seconds", "", "more than 1e8 samples; lower --seconds or --hz");
  if (!(a.noise >= 0.0) || !std::isfinite(a.noise)) throw InputError("--noise", "", "must be >= 0 degrees");
  if (!std::isfinite(a.start) || std::abs(a.start) > 9e6) throw InputError("--start", "", "must be within +-9e6 s");
  tracker::SamplingSpec s;
  s.rate_hz = a.hz;
  s.duration_s = a.seconds;
  s.start_s = a.start;
  s.noise_deg = a.noise;
  s.seed = a.seed;
  const glm::dvec3 axis = parse_axis(a.axis);
  std::vector<tracker::PoseSample> trace;
  if (a.motion == "rotate") {
    if (!std::isfinite(a.rate)) throw InputError("--rate", "", "must be finite");
    trace = tracker::constant_rotation(axis, a.rate, s);
  } else if (a.motion == "shake") {
    if (!(a.frequency > 0.0) || !std::isfinite(a.frequency)) throw InputError("--frequency", "", "must be positive");
    if (!std::isfinite(a.peak)) throw InputError("--peak", "", "must be finite");
    trace = tracker::head_shake(axis, a.peak, a.frequency, s);
  } else {
    if (!(a.period > 0.0) || !std::isfinite(a.period)) throw InputError("--period", "", "must be positive");
    if (!std::isfinite(a.amplitude)) throw InputError("--amplitude", "", "must be finite");
    trace = tracker::pendulum(axis, a.amplitude, a.period, s);
  }
  tracker::write_trace_csv(a.out, trace);
  std::printf("arpsim tracker synth: %zu samples (%s, %.3f s at %.1f Hz) -> %s\n", trace.size(), a.motion.c_str(),
              a.seconds, a.hz, a.out.c_str());
  return 0;
}

}  // namespace

Runner add_tracker_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("tracker", "Head-tracker input: find USB trackers, make synthetic traces");
  cmd->require_subcommand(1);
  CLI::App* list = cmd->add_subcommand("list", "List Oculus Rift DK1/DK2 trackers on USB");
  auto a = std::make_shared<SynthArgs>();
  CLI::App* synth = cmd->add_subcommand("synth", "Write a synthetic head-motion trace (CSV, docs/tracker.md)");
  synth->add_option("--motion", a->motion, "rotate (constant rate), shake (sinusoid), pendulum")
      ->required()
      ->check(CLI::IsMember({"rotate", "shake", "pendulum"}));
  synth->add_option("--axis", a->axis, "Rotation axis in the head frame, x,y,z (0,1,0: yaw)")->capture_default_str();
  synth->add_option("--rate", a->rate, "rotate: degrees per second")->capture_default_str();
  synth->add_option("--peak", a->peak, "shake: peak angular velocity, degrees per second")->capture_default_str();
  synth->add_option("--frequency", a->frequency, "shake: Hz")->capture_default_str();
  synth->add_option("--amplitude", a->amplitude, "pendulum: degrees")->capture_default_str();
  synth->add_option("--period", a->period, "pendulum: seconds")->capture_default_str();
  synth->add_option("--seconds", a->seconds, "Duration")->capture_default_str();
  synth->add_option("--hz", a->hz, "Sample rate")->capture_default_str();
  synth->add_option("--start", a->start, "Time of the first sample, seconds")->capture_default_str();
  synth->add_option("--noise", a->noise, "Random extra rotation per sample, degrees (standard deviation)")->capture_default_str();
  synth->add_option("--seed", a->seed, "Noise seed")->capture_default_str();
  synth->add_option("--out,-o", a->out, "Trace file to write")->required();
  return [list, a] { return list->parsed() ? run_list() : run_synth(*a); };
}

}  // namespace arp::app
