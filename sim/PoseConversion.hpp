// Tracker poses into the orientation register's input: the conversion the
// run and live commands share, and the live append that places a source's
// poses on the run's timeline.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "tracker/PoseSample.hpp"

namespace arp::sim {

// Each pose's orientation, its time moved by offset_ps.
std::vector<dp::OrientationSample> to_orientation_samples(const std::vector<tracker::PoseSample>& poses, int64_t offset_ps = 0);

// Appends live poses (times moved by offset_ps), skipping any earlier than the
// last sample the stream holds -- e.g. a report's earlier samples from before
// the run started. Returns how many were appended; with `appended`, also adds them there (times moved).
int64_t append_live_poses(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& poses, int64_t offset_ps,
                          const std::string& source, std::vector<tracker::PoseSample>* appended = nullptr);

}  // namespace arp::sim
