// The head a run turns with, as `arpsim plan` replays it: where the walk faces, with a head motion of its own on
// top (--motion, --trace), sampled as the run's orientation register holds it (the last sample at or before a
// time), and the hash a plan records for the whole motion (plan.motion_hash).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/motion/WalkPath.hpp"
#include "host/priority/Validity.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "tracker/PoseSample.hpp"
#include "tracker/SyntheticMotion.hpp"

namespace arp::sim {

// A head motion of its own: synthetic (--motion) or recorded (--trace); neither: the head only faces the walk.
struct HeadMotion {
  tracker::MotionSpec motion;
  std::string trace;
  // The trace's samples when already read (a plan reads it once for all its passes); null: each reader reads it.
  std::shared_ptr<const std::vector<tracker::PoseSample>> trace_poses;
  bool given() const { return motion.given() || !trace.empty(); }
  // InputError naming --trace when both are given (run and plan refuse them alike).
  void check() const;
  // "synthetic rotate at 300 deg/s about 0,1,0", "trace FILE", "" (none).
  std::string describe() const;
};

// On a walk the head faces where it goes, a head motion's rotation on top (in the head's frame).
void face_walk(const host::WalkPath& walk, std::vector<tracker::PoseSample>& poses);

// plan.motion_hash: the walk's alone (host::walk_hash) when the head has no motion of its own, else the walk's with the synthetic motion's parameters
// (those that shape it: the unit axis times the rate, the shake's peak or the pendulum's amplitude; the shake's
// frequency or the pendulum's period; the sampling, the noise and its seed) or the trace file's bytes. InputError naming the trace if it cannot be read.
int64_t motion_hash(const host::WalkPath& walk, const HeadMotion& head);

// The trace's samples a plan replays: walking for walk_span_s, from a second before the first frame (and the sample
// held then) to a second past the walk's end, as a run of the walk reads its window; standing (nullopt), all of them.
std::vector<tracker::PoseSample> read_planned_trace(const std::string& path, std::optional<double> walk_span_s);

// The head's turn rate over a motion starting at time 0 (a run's first frame), as a run with this walk and head
// motion takes it for its priority rule (HostSimulation::eye_turn_at): with no head motion of its own, the walk's
// facing from time 0 on (host::facing_turn_rate_rad_s); with one, the rotation between the orientations held at
// t - dt and t, the motion generated (or the trace read) from a second before 0 as a run generates it. Times asked
// for must not decrease: the motion is generated as they are asked for and dropped behind them (flat memory).
class HeadTurnRate {
 public:
  // span_s: the motion's end (a trace is read over [-1 s, span_s + 1.01 s], as a run reads its window).
  HeadTurnRate(const host::WalkPath& walk, const HeadMotion& head, double span_s);
  double at(double t_s, double dt_s);
  // The eyes' turning from it (host::eye_turn) for eyes ipd_m apart (0: one eye, which turning does not move).
  host::EyeTurn eyes_at(double t_s, double dt_s, double ipd_m) { return ipd_m == 0 ? host::EyeTurn{} : host::eye_turn(at(t_s, dt_s), ipd_m); }

 private:
  void extend_through(int64_t t_ps);
  const host::WalkPath& walk_;
  bool given_ = false;
  std::string source_;
  std::unique_ptr<tracker::MotionGenerator> generator_;  // synthetic
  std::vector<tracker::PoseSample> trace_;               // recorded, handed over once
  dp::OrientationStream stream_;
  bool started_ = false, done_ = false;
  int64_t last_ps_ = 0;
};

// The span a plan for a head standing still covers with its head motion: a trace to its last sample, a shake or
// a pendulum one period, a constant rotation one second (0: none given).
double standing_span_s(const HeadMotion& head);

}  // namespace arp::sim
