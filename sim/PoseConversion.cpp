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
  return static_cast<int64_t>(more.size());
}

int64_t live_start_offset(tracker::PoseSource& live, int64_t start_ps, std::vector<tracker::PoseSample>& before) {
  const size_t had = before.size();
  live.poll(before, 0);
  return start_ps - (before.size() > had ? before.back().time_ps : live.now_ps());
}

}  // namespace arp::sim
