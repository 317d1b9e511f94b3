// Tracker poses into the orientation register's input: the conversion the
// run and live commands share, and the live append that places a source's
// poses on the run's timeline.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "tracker/PoseSample.hpp"
#include "tracker/PoseSource.hpp"

namespace arp::sim {

// Each pose's orientation, its time moved by offset_ps.
std::vector<dp::OrientationSample> to_orientation_samples(const std::vector<tracker::PoseSample>& poses, int64_t offset_ps = 0);

// Appends live poses (times moved by offset_ps), skipping any earlier than the
// last sample the stream holds -- e.g. a report's earlier samples from before
// the run started. Returns how many were appended; with `appended`, also adds them there as the stream
// holds them (times moved, orientations normalised).
int64_t append_live_poses(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& poses, int64_t offset_ps,
                          const std::string& source, std::vector<tracker::PoseSample>* appended = nullptr);

// A live source's time against the run's, fixed as the run starts at `start_ps`. What has arrived by then
// was received while the run was being set up; the last of it is the pose at the start, and what arrives
// later is placed after it by the source's time. Judged by arrival, not by the source's time against the
// host's clock: a transport delivering slower than the device samples (a starved host) falls ever further
// behind that clock, and would have put everything the run received before its start. The source's present
// is the start when nothing has arrived, or when the source is disconnected: what it sends after a reconnection
// is timed from the host's clock again, and an anchor on a sample from before the unplug would place it late.
struct LiveStart {
  int64_t offset_ps = 0;                    // added to the source's times
  std::optional<tracker::PoseSample> pose;  // the last sample received, its time moved to the start: where the run starts
  int64_t before = 0;                       // the others received, all before the start
};
LiveStart live_start(tracker::PoseSource& live, int64_t start_ps);

}  // namespace arp::sim
