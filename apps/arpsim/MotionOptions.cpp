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
  shape(cmd.add_option("--rate", m.rate, "rotate: degrees per second")->capture_default_str());
  shape(cmd.add_option("--peak", m.peak, "shake: peak angular velocity, degrees per second")->capture_default_str());
  shape(cmd.add_option("--frequency", m.frequency, "shake: Hz")->capture_default_str());
  shape(cmd.add_option("--amplitude", m.amplitude, "pendulum: degrees")->capture_default_str());
  shape(cmd.add_option("--period", m.period, "pendulum: seconds")->capture_default_str());
  shape(cmd.add_option("--hz", m.hz, "Tracker sample rate")->capture_default_str());
  shape(cmd.add_option("--noise", m.noise, "Random extra rotation per sample, degrees (standard deviation)")->capture_default_str());
  shape(cmd.add_option("--seed", m.seed, "Noise seed")->capture_default_str());
}

}  // namespace arp::app
