// Importing public head-motion datasets laid out as one sample per line,
//   timestamp frameId w x y z
// (whitespace- or comma-separated; '#' comments and one header line allowed),
// the layout of 360-degree-video head-movement datasets. Everything that
// differs between datasets is stated, not guessed:
//   - time unit of the timestamp (s, ms, us, ns); the first sample becomes time 0;
//   - quaternion order: w x y z (default) or x y z w (`scalar_last`);
//   - axes: "gl" -- right-handed, x right, y up, looking down -z, as arpsim;
//     "unity" -- left-handed, x right, y up, looking down +z (Unity, most
//     360-video players). Unity quaternions are mirrored through the z = 0
//     plane into arpsim's frame: (w, x, y, z) -> (w, -x, -y, z), so a turn to
//     the right stays a turn to the right.
// Quaternions must be non-zero and unit within 1e-2 (datasets store floats);
// they are renormalised. Timestamps must increase strictly; frame ids must be
// integers. Every problem is an InputError naming the file, the line and the reason.
#pragma once
#include <string>
#include <vector>

#include "PoseSample.hpp"

namespace arp::tracker {

struct DatasetLayout {
  enum class TimeUnit { Seconds, Milliseconds, Microseconds, Nanoseconds };
  enum class Axes { OpenGl, Unity };
  TimeUnit time_unit = TimeUnit::Seconds;
  Axes axes = Axes::OpenGl;
  bool scalar_last = false;
};

bool parse_time_unit(const std::string& s, DatasetLayout::TimeUnit& out);  // s, ms, us, ns
bool parse_axes(const std::string& s, DatasetLayout::Axes& out);           // gl, unity

std::vector<PoseSample> read_head_motion_dataset(const std::string& path, const DatasetLayout& layout);

}  // namespace arp::tracker
