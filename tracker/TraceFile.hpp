// Head-motion trace files: arpsim's documented CSV (docs/tracker.md).
//
//   # comment lines start with '#'
//   time_s,qw,qx,qy,qz            (or with position: time_s,qw,qx,qy,qz,px,py,pz)
//   0.000000000,1,0,0,0
//
// time_s is seconds on the simulated timeline; the quaternion (w x y z)
// rotates head-frame directions (x right, y up, looking down -z) into the
// world frame and must be unit length (within 1e-3) -- it is renormalised on
// reading; px py pz are metres in the world frame. Times never decrease.
// Every problem is an InputError naming the file, the line and the reason.
#pragma once
#include <string>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

std::vector<PoseSample> read_trace_csv(const std::string& path);

// Writes through a temporary file and a rename: never a half-written trace.
// Positions are written when every sample has one.
void write_trace_csv(const std::string& path, const std::vector<PoseSample>& samples);

}  // namespace arp::tracker
