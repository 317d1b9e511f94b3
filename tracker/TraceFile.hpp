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
//
// Reading streams: the file is read line by line (lines of at most 64 KiB,
// no binary data), and with a time window only the samples a run can use are
// kept -- the last at or before the window's start, every one inside it and
// the first after its end, where reading stops (times never decrease, so the
// rest cannot matter). A ten-million-line trace then costs a 3-frame run
// nothing but the reading of its first seconds (and, with a planned
// configuration, one pass over its bytes: sim::motion_hash, plan.motion_hash).
#pragma once
#include <cstdint>
#include <cstdio>
#include <istream>
#include <limits>
#include <string>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

struct TraceWindow {
  int64_t from_ps = std::numeric_limits<int64_t>::min();
  int64_t to_ps = std::numeric_limits<int64_t>::max();
};

// A trace file, or standard input for "-".
std::vector<PoseSample> read_trace_csv(const std::string& path, const TraceWindow& window = {});
std::vector<PoseSample> read_trace_csv(std::istream& in, const std::string& source, const TraceWindow& window = {});

// Writes through a temporary file and a rename: never a half-written trace.
// Positions are written when every sample has one.
void write_trace_csv(const std::string& path, const std::vector<PoseSample>& samples);

// A trace written as it comes, in flat memory (a live run's motion, an hour of it): into a temporary
// file beside `path`, renamed to it by commit(); destroyed uncommitted (an error, an interruption) it
// leaves nothing. Opening checks that the file can be written before any work is done. Times must not
// decrease (std::invalid_argument otherwise); with `positions` every sample must have one.
class TraceWriter {
 public:
  TraceWriter(const std::string& path, bool positions);  // InputError naming `path` when it cannot be written
  ~TraceWriter();
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;
  void append(const PoseSample& s);
  void commit();
  int64_t written() const { return written_; }

 private:
  std::string failure();  // ": reason" of the first failed write, or ""
  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  bool positions_, ok_ = true;
  int errno_ = 0;  // kept at the first failed write
  int64_t written_ = 0, last_ps_ = 0;
};

}  // namespace arp::tracker
