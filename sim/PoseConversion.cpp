#include "sim/PoseConversion.hpp"

namespace arp::sim {

std::vector<dp::OrientationSample> to_orientation_samples(const std::vector<tracker::PoseSample>& poses, int64_t offset_ps) {
  std::vector<dp::OrientationSample> s;
  s.reserve(poses.size());
  for (const auto& p : poses)
    s.push_back({p.time_ps + offset_ps, dp::Quat{p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}});
  return s;
}

int64_t append_live_poses(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& poses, int64_t offset_ps,
                          const std::string& source, std::vector<tracker::PoseSample>* appended) {
  std::vector<dp::OrientationSample> more;
  int64_t last = stream[stream.size() - 1].time_ps;
  const std::vector<dp::OrientationSample> all = to_orientation_samples(poses, offset_ps);
  const size_t first = appended ? appended->size() : 0;
  for (size_t i = 0; i < all.size(); ++i)
    if (all[i].time_ps >= last) {
      more.push_back(all[i]);
      last = all[i].time_ps;
      if (appended) {
        appended->push_back(poses[i]);
        appended->back().time_ps = all[i].time_ps;
      }
    }
  stream.append(more, source);
  if (appended)  // as the stream holds them (normalised): a recording replays the same orientations
    for (size_t k = 0; k < more.size(); ++k) {
      const dp::Quat& q = stream[stream.size() - more.size() + k].q;
      (*appended)[first + k].orientation = glm::dquat(q.w, q.x, q.y, q.z);
    }
  return static_cast<int64_t>(more.size());
}

LiveStart live_start(tracker::PoseSource& live, int64_t start_ps) {
  std::vector<tracker::PoseSample> got;
  live.poll(got, 0);
  LiveStart s;
  s.offset_ps = start_ps - (!got.empty() && live.connected() ? got.back().time_ps : live.now_ps());
  if (!got.empty()) {
    s.pose = got.back();
    s.pose->time_ps = start_ps - s.offset_ps;
    s.before = static_cast<int64_t>(got.size()) - 1;
  }
  return s;
}

}  // namespace arp::sim
