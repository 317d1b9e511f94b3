#include "sim/LiveIntake.hpp"

#include <stdexcept>

#include "common/InputError.hpp"
#include "sim/PoseConversion.hpp"

namespace arp::sim {

void check_record_live(const std::string& record_path, bool live) {
  if (!record_path.empty() && !live)
    throw InputError("--record-live", record_path, "records the motion of live input: use it with --live usb");
}

LiveIntake::LiveIntake(tracker::PoseSource& source, const std::string& record_path) : source_(source) {
  if (!record_path.empty()) record_ = std::make_unique<tracker::TraceWriter>(record_path, false);
}

LiveIntake::~LiveIntake() = default;

void LiveIntake::start(dp::OrientationStream& stream, int64_t start_ps, const std::string& stream_source) {
  const LiveStart s = live_start(source_, start_ps);
  started_ = true;
  offset_ps_ = s.offset_ps;
  start_ps_ = start_ps;
  before_start_ += s.before;
  tracker::PoseSample at_start;  // nothing received yet: the pose the register holds (its reset value), taken the same way
  if (s.pose) {
    at_start = *s.pose;  // the run starts where the head is (not at the identity until the next sample)
  } else {
    const dp::Quat q = stream[stream.index_at(start_ps)].q;
    at_start.time_ps = start_ps - offset_ps_;
    at_start.orientation = glm::dquat(q.w, q.x, q.y, q.z);
  }
  // Taken into the run and recorded: a recording replays from the start (`run --trace` holds a trace's
  // first sample back to the start, so without it the replay would show the first sample too early).
  take(stream, {at_start}, stream_source);
}

void LiveIntake::take(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& got, const std::string& stream_source) {
  if (!started_) throw std::logic_error("LiveIntake::take before start");
  appended_.clear();
  const int64_t n = append_live_poses(stream, got, offset_ps_, stream_source, record_ ? &appended_ : nullptr);
  for (const auto& p : appended_) record_->append(p);
  taken_ += n;
  // Every sample timed before the start is left out (the stream holds the pose at the start); the others
  // left out stepped back in time.
  int64_t before = 0;
  for (const auto& p : got) before += p.time_ps + offset_ps_ < start_ps_ ? 1 : 0;
  before_start_ += before;
  out_of_order_ += static_cast<int64_t>(got.size()) - n - before;
}

int64_t LiveIntake::recorded() const { return record_ ? record_->written() : 0; }

void LiveIntake::commit_record() {
  if (record_) record_->commit();
}

}  // namespace arp::sim
