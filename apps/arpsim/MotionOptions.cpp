#include "MotionOptions.hpp"

#include "CommonOptions.hpp"

namespace arp::app {

void add_device_option(CLI::App& cmd, tracker::TrackerChoice& choice) {
  cmd.add_option("--device", choice.device,
                 "Which tracker, when several are attached: its serial number or BUS:ADDR (as `arpsim tracker list` shows them)");
  cmd.add_option("--mag-yaw", choice.mag_yaw_gain,
                 "Correct yaw drift from the tracker's magnetometer, removing this fraction of the heading error per second "
                 "(0.1 is a good start; 0: off). For a calibrated magnetometer, or with --mag-calibrate (docs/tracker.md)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd.add_flag("--mag-calibrate", choice.mag_calibrate,
               "With --mag-yaw: learn the magnetometer's own field (hard iron) as the head looks around, and correct the yaw "
               "only once it is known (look around, up and down, for a minute)");
}

void add_record_live_option(CLI::App& cmd, std::string& path) {
  cmd.add_option("--record-live", path,
                 "With --live: write the motion the pipeline took (on the run's timeline) as a trace file, to replay it with "
                 "`arpsim run --trace`")
      ->check(output_name());
}

void add_motion_options(CLI::App& cmd, tracker::MotionSpec& m, bool required, bool shape_needs_motion) {
  auto* o = cmd.add_option("--motion", m.motion, "Synthetic motion: rotate (constant rate), shake (sinusoid), pendulum")
                ->check(CLI::IsMember({"rotate", "shake", "pendulum"}));
  if (required) o->required();
  // The shape of a motion means nothing without one: given alone, it is refused rather than silently unused.
  auto shape = [&](CLI::Option* opt) {
    if (shape_needs_motion) opt->needs(o);
  };
  shape(cmd.add_option("--axis", m.axis, "Rotation axis in the head frame, x,y,z (0,1,0: yaw)")->capture_default_str());
  CLI::Option* rate = cmd.add_option("--rate", m.rate, "rotate: degrees per second")->capture_default_str();
  CLI::Option* peak = cmd.add_option("--peak", m.peak, "shake: peak angular velocity, degrees per second")->capture_default_str();
  CLI::Option* frequency = cmd.add_option("--frequency", m.frequency, "shake: Hz")->capture_default_str();
  CLI::Option* amplitude = cmd.add_option("--amplitude", m.amplitude, "pendulum: degrees")->capture_default_str();
  CLI::Option* period = cmd.add_option("--period", m.period, "pendulum: seconds")->capture_default_str();
  for (CLI::Option* opt : {rate, peak, frequency, amplitude, period}) shape(opt);
  shape(cmd.add_option("--hz", m.hz, "Tracker sample rate")->capture_default_str());
  shape(cmd.add_option("--noise", m.noise, "Random extra rotation per sample, degrees (standard deviation)")->capture_default_str());
  CLI::Option* seed = cmd.add_option("--seed", m.seed, "Noise seed (with --noise)")->capture_default_str();
  shape(seed);
  // Nor is a shape of another motion than the one played, or a seed of no noise: they changed nothing, without a word.
  const std::string played = shape_needs_motion ? "" : "shake";  // (without --motion: that default)
  cmd.parse_complete_callback([&m, rate, peak, frequency, amplitude, period, seed, played] {
    const std::string motion = m.motion.empty() ? played : m.motion;
    if (motion.empty()) return;
    for (const auto& [opt, for_motion] : {std::pair{rate, "rotate"}, {peak, "shake"}, {frequency, "shake"}, {amplitude, "pendulum"},
                                          {period, "pendulum"}})
      if (opt->count() > 0 && motion != for_motion)
        throw CLI::ValidationError(opt->get_name(), std::string("shapes --motion ") + for_motion + ", and " +
                                                        (m.motion.empty() ? "no --motion is given (the default " + motion + " plays, or a --trace)"
                                                                          : "the motion is " + motion) +
                                                        ": it would change nothing");
    if (seed->count() > 0 && m.noise == 0)
      throw CLI::ValidationError("--seed", "seeds --noise, which is 0: it would change nothing");
  });
}

}  // namespace arp::app
