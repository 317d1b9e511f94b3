#include "sim/LiveIntake.hpp"

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
  offset_ps_ = s.offset_ps;
  before_start_ += s.before;
  if (s.pose) take(stream, {*s.pose}, stream_source);  // the run starts where the head is (not at the identity until the next sample)
}

void LiveIntake::take(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& got, const std::string& stream_source) {
  appended_.clear();
  const int64_t n = append_live_poses(stream, got, offset_ps_, stream_source, record_ ? &appended_ : nullptr);
  for (const auto& p : appended_) record_->append(p);
  taken_ += n;
  before_start_ += static_cast<int64_t>(got.size()) - n;
}

int64_t LiveIntake::recorded() const { return record_ ? record_->written() : 0; }

void LiveIntake::commit_record() {
  if (record_) record_->commit();
}

}  // namespace arp::sim
