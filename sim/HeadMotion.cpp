#include "HeadMotion.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

#include "PoseConversion.hpp"
#include "common/Fingerprint.hpp"
#include "common/InputError.hpp"
#include "common/InputFile.hpp"
#include "common/PrintfText.hpp"
#include "common/Units.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::sim {

std::string HeadMotion::describe() const {
  if (!trace.empty()) return "trace " + trace;
  if (!motion.given()) return "";
  const tracker::MotionSpec& m = motion;
  const std::string about = " about " + m.axis;
  if (m.motion == "rotate") return "synthetic rotate at " + printf_text("%g", m.rate) + " deg/s" + about;
  if (m.motion == "shake")
    return "synthetic shake at " + printf_text("%g", m.peak) + " deg/s peak, " + printf_text("%g", m.frequency) + " Hz" + about;
  return "synthetic pendulum of " + printf_text("%g", m.amplitude) + " deg, " + printf_text("%g", m.period) + " s" + about;
}

void HeadMotion::check() const {
  if (!trace.empty() && motion.given()) throw InputError("--trace", "", "give either --trace or --motion, not both");
}

std::vector<tracker::PoseSample> read_planned_trace(const std::string& path, std::optional<double> walk_span_s) {
  if (!walk_span_s) return tracker::read_trace_csv(path);
  return tracker::read_trace_csv(path, {-kPsPerSecond, seconds_to_ps(std::min(*walk_span_s + 1.01, tracker::kPoseTimeLimitS))});
}

void face_walk(const host::WalkPath& walk, std::vector<tracker::PoseSample>& poses) {
  for (auto& p : poses) p.orientation = walk.facing(ps_to_seconds(p.time_ps)) * p.orientation;
}

int64_t motion_hash(const host::WalkPath& walk, const HeadMotion& head) {
  const int64_t of_walk = host::walk_hash(walk);
  if (!head.given()) return of_walk;
  Fingerprint h;
  h.add(static_cast<uint64_t>(of_walk));
  if (!head.trace.empty()) {
    h.add(std::string("trace"));
    // Standard input is read once, by the run: it is no file a plan was made from (plan refuses it).
    if (head.trace == "-") return h.add(std::string("standard input")).key();
    // A regular file only (a FIFO or a device would block or never end), as the trace reader takes it.
    const std::unique_ptr<std::istream> in = open_input_stream(head.trace, "trace file");
    std::string chunk(1 << 16, '\0');
    while (in->read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in->gcount() > 0)
      h.add(chunk.substr(0, static_cast<size_t>(in->gcount())));
    return h.key();
  }
  const tracker::MotionSpec& m = head.motion;
  // The rotation as the unit axis times its signed size (the rate, the shake's peak, the pendulum's amplitude): an axis
  // written longer ("0,2,0") or reversed with its size ("0,-1,0" at -30 deg/s) turns the head as "0,1,0" at 30 does,
  // sample for sample. (+ 0.0: a zero component's sign, which the product can flip, is not the motion's.)
  const double size = m.motion == "rotate" ? m.rate : m.motion == "shake" ? m.peak : m.amplitude;
  const glm::dvec3 turn = tracker::unit_axis(tracker::parse_axis(m.axis)) * size;
  h.add(m.motion).add(turn.x + 0.0).add(turn.y + 0.0).add(turn.z + 0.0).add(m.hz).add(m.noise);
  if (m.noise > 0) h.add(m.seed);
  if (m.motion == "shake") h.add(m.frequency);
  else if (m.motion == "pendulum") h.add(m.period);
  return h.key();
}

double standing_span_s(const HeadMotion& head) {
  if (!head.trace.empty()) {
    const auto poses = head.trace_poses ? head.trace_poses
                                        : std::make_shared<const std::vector<tracker::PoseSample>>(read_planned_trace(head.trace, std::nullopt));
    return poses->empty() ? 0.0 : std::max(0.0, ps_to_seconds(poses->back().time_ps));
  }
  if (!head.motion.given()) return 0.0;
  const tracker::MotionSpec& m = head.motion;
  if (m.motion == "shake") {
    if (!(m.frequency > 0) || !std::isfinite(m.frequency)) throw InputError("--frequency", "", "must be positive");
    return 1.0 / m.frequency;
  }
  if (m.motion == "pendulum") {
    if (!(m.period > 0) || !std::isfinite(m.period)) throw InputError("--period", "", "must be positive");
    return m.period;
  }
  return 1.0;
}

HeadTurnRate::HeadTurnRate(const host::WalkPath& walk, const HeadMotion& head, double span_s)
    : walk_(walk), given_(head.given()) {
  if (!given_) return;
  const double end_s = std::min(span_s + 1.01, tracker::kPoseTimeLimitS);
  if (!head.trace.empty()) {
    source_ = head.trace;
    trace_ = head.trace_poses ? *head.trace_poses : read_planned_trace(head.trace, span_s);
  } else {
    source_ = "synthetic " + head.motion.motion;
    // (The generator's own limit names its --seconds, which plan has not got.)
    if ((end_s + 1.0) * head.motion.hz > 1e8)
      throw InputError("--motion", head.motion.motion,
                       "the motion planned over lasts " + printf_text("%.4g", span_s) + " s: more than 1e8 samples at --hz " +
                           printf_text("%g", head.motion.hz) + " (a shorter motion, or a lower --hz)");
    // As a run from frame 0 generates it: from a second before the first frame (the noise in the same order).
    generator_ = std::make_unique<tracker::MotionGenerator>(head.motion.generator(-1.0, end_s + 1.0));
  }
}

void HeadTurnRate::extend_through(int64_t t_ps) {
  if (done_ || (started_ && last_ps_ > t_ps)) return;
  std::vector<tracker::PoseSample> more;
  if (generator_) {
    generator_->take_through(t_ps, more);
    done_ = generator_->done();
  } else {
    more = std::move(trace_);
    trace_.clear();
    done_ = true;
  }
  if (more.empty()) return;
  face_walk(walk_, more);
  last_ps_ = more.back().time_ps;
  if (!started_) stream_ = dp::OrientationStream(to_orientation_samples(more), source_);
  else stream_.append(to_orientation_samples(more), source_);
  started_ = true;
}

double HeadTurnRate::at(double t_s, double dt_s) {
  if (!given_) return host::facing_turn_rate_rad_s(walk_, t_s, dt_s, 0.0);
  auto head = [this](double s) {  // the orientation held at s, as the run's host reads its stream
    const int64_t s_ps = seconds_to_ps(s);
    extend_through(s_ps);
    const dp::Quat& q = stream_[stream_.index_at(s_ps)].q;
    return glm::dquat(q.w, q.x, q.y, q.z);
  };
  const double rate = host::turn_rate_rad_s(head, t_s, dt_s);
  if (started_) stream_.discard_before(seconds_to_ps(t_s - dt_s));
  return rate;
}

}  // namespace arp::sim
