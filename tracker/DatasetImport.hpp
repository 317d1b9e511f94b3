// Importing public head-motion datasets: one sample per line, columns
// separated by commas or tabs (or, when the first line has neither, by any of
// spaces, commas and tabs); '#' comments and one header line allowed. What
// differs between datasets is stated as data, never guessed:
//   - which column holds what, by 1-based number or by header name: the time,
//     an optional frame id, and either a quaternion (qw qx qy qz) or Euler
//     angles (rx ry rz: angles about the dataset's own x, y, z axes, applied
//     in a stated intrinsic order, in degrees or radians);
//   - the time unit (s, ms, us, ns); the first sample becomes time 0;
//   - the dataset's axes, as the arpsim directions its x, y and z axes point
//     in (arpsim: x right, y up, looking down -z). Any signed permutation:
//     "+x,+y,-z" is Unity's left-handed frame, "-z,-x,+y" a z-up frame looking
//     down +x (the recorder of Corbillon et al. 2017). The dataset's rotation
//     R becomes M R M^T: "looking forward and level" (the dataset's identity)
//     stays the identity, a turn to the right stays a turn to the right.
// Quaternions must be non-zero and unit within 1e-2 (datasets store floats);
// they are renormalised. Timestamps never go back (equal ones are kept, as
// trace files allow); frame ids are non-negative integers. Every problem is
// an InputError naming the file, the line and the reason.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "PoseSample.hpp"

namespace arp::tracker {

struct DatasetLayout {
  enum class TimeUnit { Seconds, Milliseconds, Microseconds, Nanoseconds };
  enum class AngleUnit { Degrees, Radians };
  // A column: its 1-based number or its header name (matched ignoring case); empty: absent.
  struct Columns {
    std::string time = "1", frame = "2", qw = "3", qx = "4", qy = "5", qz = "6", rx, ry, rz;
  };
  TimeUnit time_unit = TimeUnit::Seconds;
  Columns columns;
  std::string euler_order = "yxz";  // "abc": R = R_a(r_a) R_b(r_b) R_c(r_c), each about the dataset's axis
  AngleUnit angle_unit = AngleUnit::Degrees;
  glm::dmat3 axes{1.0};  // column i: the arpsim direction of the dataset's axis i (a signed permutation)
};

// Command-line forms; false (with the reason in `why`) for a bad value.
bool parse_time_unit(const std::string& s, DatasetLayout::TimeUnit& out);  // s, ms, us, ns
bool parse_angle_unit(const std::string& s, DatasetLayout::AngleUnit& out);  // deg, rad
// gl, unity, corbillon, or three signed axes "A,B,C" (A: where the dataset's x points, e.g. "+x,+y,-z").
bool parse_axes(const std::string& s, glm::dmat3& out, std::string& why);
// "role=column,..." with roles t, frame, qw, qx, qy, qz, rx, ry, rz; the roles not listed are absent.
bool parse_columns(const std::string& s, DatasetLayout::Columns& out, std::string& why);
bool parse_euler_order(const std::string& s, std::string& out, std::string& why);  // three distinct of x, y, z

// The layout's own consistency (a time column; a whole quaternion or whole
// Euler angles, not both); empty when it is usable.
std::string layout_problem(const DatasetLayout& layout);

// A layout as the command line states it (arpsim tracker import).
struct DatasetLayoutOptions {
  std::string time_unit = "s", axes = "gl", columns, euler, angle_unit = "deg";
  bool scalar_last = false;  // the quaternion columns are x y z w
};
// The layout those options state; a bad or contradictory option is an
// InputError naming it (--time-unit, --axes, --columns, --euler, ...).
DatasetLayout dataset_layout(const DatasetLayoutOptions& o);

std::vector<PoseSample> read_head_motion_dataset(const std::string& path, const DatasetLayout& layout);

}  // namespace arp::tracker
