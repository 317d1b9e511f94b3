#include "DatasetImport.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "common/InputError.hpp"
#include "common/InputFile.hpp"
#include "common/Units.hpp"

namespace arp::tracker {

bool parse_time_unit(const std::string& s, DatasetLayout::TimeUnit& out) {
  using U = DatasetLayout::TimeUnit;
  if (s == "s") out = U::Seconds;
  else if (s == "ms") out = U::Milliseconds;
  else if (s == "us") out = U::Microseconds;
  else if (s == "ns") out = U::Nanoseconds;
  else return false;
  return true;
}

bool parse_angle_unit(const std::string& s, DatasetLayout::AngleUnit& out) {
  if (s == "deg") out = DatasetLayout::AngleUnit::Degrees;
  else if (s == "rad") out = DatasetLayout::AngleUnit::Radians;
  else return false;
  return true;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& s, const char* seps) {
  std::vector<std::string> out;
  size_t at = 0;
  while (true) {
    const size_t e = s.find_first_of(seps, at);
    out.push_back(trim_blanks(s.substr(at, e == std::string::npos ? std::string::npos : e - at)));
    if (e == std::string::npos) return out;
    at = e + 1;
  }
}

bool number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

// Reads as a number of any kind (nan and inf too): a line with one is data, never a header.
bool numeric_looking(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// The arpsim axis a signed axis name points along: "+x" / "x" / "-y" ...
bool signed_axis(const std::string& s, glm::dvec3& out) {
  const std::string t = lower(trim_blanks(s));
  if (t.empty() || t.size() > 2) return false;
  const char a = t.back();
  const double sign = t.size() == 2 ? (t[0] == '-' ? -1.0 : t[0] == '+' ? 1.0 : 0.0) : 1.0;
  if (sign == 0.0 || a < 'x' || a > 'z') return false;
  out = glm::dvec3(0.0);
  out[a - 'x'] = sign;
  return true;
}

}  // namespace

bool parse_axes(const std::string& s, glm::dmat3& out, std::string& why) {
  const std::string t = lower(s);
  std::string spec = t;
  if (t == "gl") spec = "+x,+y,+z";
  else if (t == "unity") spec = "+x,+y,-z";           // left-handed, y up, looking down +z
  else if (t == "corbillon") spec = "-z,-x,+y";       // right-handed, z up, looking down +x, y to the left
  const std::vector<std::string> parts = split(spec, ",");
  if (parts.size() != 3) {
    why = "must be gl, unity, corbillon or three signed axes such as +x,+y,-z (where the dataset's x, y, z point)";
    return false;
  }
  glm::dmat3 m(0.0);
  for (int i = 0; i < 3; ++i)
    if (!signed_axis(parts[static_cast<size_t>(i)], m[i])) {
      why = "'" + quoted(parts[static_cast<size_t>(i)]) + "' is not a signed axis (+x, -x, +y, -y, +z or -z)";
      return false;
    }
  const glm::dvec3 used = glm::abs(m[0]) + glm::abs(m[1]) + glm::abs(m[2]);
  if (used != glm::dvec3(1.0)) {
    why = "each of x, y and z must be used once";
    return false;
  }
  out = m;
  return true;
}

bool parse_columns(const std::string& s, DatasetLayout::Columns& out, std::string& why) {
  DatasetLayout::Columns c{"", "", "", "", "", "", "", "", ""};
  for (const std::string& item : split(s, ",")) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      why = "'" + quoted(item) + "' is not ROLE=COLUMN (a column number from 1 or a header name)";
      return false;
    }
    const std::string role = lower(trim_blanks(item.substr(0, eq))), col = trim_blanks(item.substr(eq + 1));
    std::string* slot = role == "t" || role == "time" ? &c.time
                        : role == "frame"             ? &c.frame
                        : role == "qw"                ? &c.qw
                        : role == "qx"                ? &c.qx
                        : role == "qy"                ? &c.qy
                        : role == "qz"                ? &c.qz
                        : role == "rx"                ? &c.rx
                        : role == "ry"                ? &c.ry
                        : role == "rz"                ? &c.rz
                                                      : nullptr;
    if (!slot) {
      why = "unknown role '" + quoted(role) + "' (t, frame, qw, qx, qy, qz, rx, ry, rz)";
      return false;
    }
    if (!slot->empty()) {
      why = "role '" + role + "' given twice";
      return false;
    }
    *slot = col;
  }
  out = c;
  return true;
}

bool parse_euler_order(const std::string& s, std::string& out, std::string& why) {
  const std::string t = lower(s);
  if (t.size() != 3 || std::count(t.begin(), t.end(), 'x') != 1 || std::count(t.begin(), t.end(), 'y') != 1 ||
      std::count(t.begin(), t.end(), 'z') != 1) {
    why = "must name x, y and z once each, outermost first (e.g. yxz: yaw, then pitch, then roll for a y-up frame)";
    return false;
  }
  out = t;
  return true;
}

std::string layout_problem(const DatasetLayout& l) {
  const auto& c = l.columns;
  if (c.time.empty()) return "no time column";
  const int quat = !c.qw.empty() + !c.qx.empty() + !c.qy.empty() + !c.qz.empty();
  const int euler = !c.rx.empty() + !c.ry.empty() + !c.rz.empty();
  if (quat && euler) return "give a quaternion (qw qx qy qz) or Euler angles (rx ry rz), not both";
  if (quat != 4 && euler != 3) return "the orientation needs all of qw, qx, qy, qz or all of rx, ry, rz";
  std::string why, order;
  // Exactly as the reader uses it: lower-case x, y, z once each.
  if (euler && (!parse_euler_order(l.euler_order, order, why) || order != l.euler_order))
    return "Euler order '" + quoted(l.euler_order) + "' must name x, y and z once each, in lower case";
  return "";
}

DatasetLayout dataset_layout(const DatasetLayoutOptions& o) {
  DatasetLayout layout;
  std::string why;
  if (!parse_time_unit(o.time_unit, layout.time_unit)) throw InputError("--time-unit", o.time_unit, "must be s, ms, us or ns");
  if (!parse_angle_unit(o.angle_unit, layout.angle_unit)) throw InputError("--angle-unit", o.angle_unit, "must be deg or rad");
  if (!parse_axes(o.axes, layout.axes, why)) throw InputError("--axes", o.axes, why);
  if (o.scalar_last && !o.columns.empty()) throw InputError("--scalar-last", "", "give --columns or --scalar-last, not both");
  if (o.scalar_last) layout.columns = {"1", "2", "6", "3", "4", "5", "", "", ""};
  if (!o.columns.empty() && !parse_columns(o.columns, layout.columns, why)) throw InputError("--columns", o.columns, why);
  if (!o.euler.empty()) {
    if (!parse_euler_order(o.euler, layout.euler_order, why)) throw InputError("--euler", o.euler, why);
    if (o.columns.empty()) throw InputError("--euler", o.euler, "needs --columns naming the angle columns rx, ry, rz");
  }
  if (const std::string p = layout_problem(layout); !p.empty()) throw InputError("--columns", o.columns, p);
  if (layout.columns.rx.empty() && !o.euler.empty()) throw InputError("--euler", o.euler, "the columns hold a quaternion, not angles");
  return layout;
}

namespace {

// The roles, in a fixed order; kTime..kQz/kRz index into it.
enum Role { kTime, kFrame, kQw, kQx, kQy, kQz, kRx, kRy, kRz, kRoles };
constexpr const char* kRoleName[kRoles] = {"time", "frame", "qw", "qx", "qy", "qz", "rx", "ry", "rz"};

std::array<std::string, kRoles> role_specs(const DatasetLayout::Columns& c) {
  return {c.time, c.frame, c.qw, c.qx, c.qy, c.qz, c.rx, c.ry, c.rz};
}

// The rotation in the dataset's frame carried into arpsim's: for a signed
// permutation M, M R M^T is the rotation by the same angle about det(M) M axis.
// Done per component (each arpsim component is plus or minus one dataset
// component), so it is exact, and "+ 0.0" keeps "-0" out of the trace.
glm::dquat into_arpsim(const glm::dquat& q, const glm::dmat3& m) {
  const double det = glm::determinant(m);
  const glm::dvec3 v = det * (m * glm::dvec3(q.x, q.y, q.z));
  return glm::dquat(q.w, v.x + 0.0, v.y + 0.0, v.z + 0.0);
}

}  // namespace

std::vector<PoseSample> read_head_motion_dataset(const std::string& path, const DatasetLayout& layout) {
  if (const std::string p = layout_problem(layout); !p.empty()) throw InputError(path, "", "the layout: " + p);
  const auto in = open_input_stream(path, "dataset file");
  LineReader lines(*in, path);
  double to_ps = 1e12;
  switch (layout.time_unit) {
    case DatasetLayout::TimeUnit::Seconds: to_ps = 1e12; break;
    case DatasetLayout::TimeUnit::Milliseconds: to_ps = 1e9; break;
    case DatasetLayout::TimeUnit::Microseconds: to_ps = 1e6; break;
    case DatasetLayout::TimeUnit::Nanoseconds: to_ps = 1e3; break;
  }
  const bool euler = !layout.columns.rx.empty();
  const double to_rad = layout.angle_unit == DatasetLayout::AngleUnit::Degrees ? kPi / 180.0 : 1.0;
  const auto specs = role_specs(layout.columns);

  std::vector<PoseSample> out;
  std::string line, first_where;
  const char* seps = nullptr;   // decided by the first line
  size_t width = 0;              // columns per line, from the first line
  std::array<int, kRoles> col;   // 0-based column of each role, -1 when absent
  col.fill(-1);
  bool resolved = false, first_data = true;
  double t0 = 0;
  while (lines.next(line)) {
    const std::string where = lines.where();
    const std::string t = trim_blanks(line);
    if (t.empty() || t[0] == '#') continue;
    if (!seps) {
      seps = t.find_first_of(",\t") != std::string::npos ? ",\t" : " ,\t";
      first_where = where;
    }
    std::vector<std::string> f = split(t, seps);
    if (seps[0] == ' ') f.erase(std::remove(f.begin(), f.end(), std::string()), f.end());  // runs of spaces
    if (!resolved) {
      // The first line: a header when no field is a number (a data line with a bad field is reported, not skipped).
      const bool header = std::none_of(f.begin(), f.end(), numeric_looking);
      width = f.size();
      for (int r = 0; r < kRoles; ++r) {
        const std::string& s = specs[static_cast<size_t>(r)];
        if (s.empty()) continue;
        const bool numeric = std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (numeric) {
          const long n = s.size() <= 6 ? std::atol(s.c_str()) : 0;
          if (n < 1 || static_cast<size_t>(n) > width)
            throw InputError(path, where, std::string("the ") + kRoleName[r] + " column " + quoted(s) + " is not one of the " +
                                              std::to_string(width) + " columns");
          col[static_cast<size_t>(r)] = static_cast<int>(n - 1);
        } else {
          if (!header) throw InputError(path, where, "columns are named ('" + quoted(s) + "') but the file has no header line");
          auto named = [&s](const std::string& h) { return lower(h) == lower(s); };
          const auto it = std::find_if(f.begin(), f.end(), named);
          if (it == f.end()) throw InputError(path, where, std::string("the header has no column '") + quoted(s) + "' (the " + kRoleName[r] + ")");
          if (std::count_if(f.begin(), f.end(), named) > 1)
            throw InputError(path, where, "the header names '" + quoted(s) + "' more than once: give its number instead");
          col[static_cast<size_t>(r)] = static_cast<int>(it - f.begin());
        }
      }
      for (int r = 0; r < kRoles; ++r)
        for (int q = r + 1; q < kRoles; ++q)
          if (col[static_cast<size_t>(r)] >= 0 && col[static_cast<size_t>(r)] == col[static_cast<size_t>(q)])
            throw InputError(path, where, std::string("the ") + kRoleName[r] + " and the " + kRoleName[q] + " are the same column");
      resolved = true;
      if (header) continue;
    }
    if (f.size() != width)
      throw InputError(path, where, "expected " + std::to_string(width) + " columns (as " + first_where + "), found " + std::to_string(f.size()));
    double v[kRoles] = {};
    for (int r = 0; r < kRoles; ++r) {
      const int c = col[static_cast<size_t>(r)];
      if (c < 0) continue;
      const std::string& s = f[static_cast<size_t>(c)];
      if (!number(s, v[r])) {
        const char* what = r == kTime ? "timestamp" : r == kFrame ? "frame id" : euler ? "angle" : "quaternion";
        throw InputError(path, where, std::string(what) + " '" + quoted(s) + "' is not a finite number");
      }
    }
    if (col[kFrame] >= 0 && (v[kFrame] != std::floor(v[kFrame]) || v[kFrame] < 0))
      throw InputError(path, where, "frame id '" + quoted(f[static_cast<size_t>(col[kFrame])]) + "' is not a non-negative integer");
    glm::dquat q;
    if (euler) {
      q = glm::dquat(1.0, 0.0, 0.0, 0.0);
      for (const char a : layout.euler_order) {
        glm::dvec3 axis(0.0);
        axis[a - 'x'] = 1.0;
        q = q * glm::angleAxis(v[kRx + (a - 'x')] * to_rad, axis);
      }
    } else {
      q = glm::dquat(v[kQw], v[kQx], v[kQy], v[kQz]);
      const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
      if (n == 0) throw InputError(path, where, "the quaternion is zero");
      if (std::abs(n - 1) > 1e-2) throw InputError(path, where, "the quaternion is not unit length (norm " + std::to_string(n) + ")");
      q = glm::dquat(q.w / n, q.x / n, q.y / n, q.z / n);
    }
    if (first_data) t0 = v[kTime];
    const double t_ps = (v[kTime] - t0) * to_ps;
    if (std::abs(t_ps) > 9e18) throw InputError(path, where, "timestamp out of range for the time unit");
    const int64_t time_ps = static_cast<int64_t>(std::llround(t_ps));
    if (!first_data && time_ps < out.back().time_ps)
      throw InputError(path, where, "timestamp " + quoted(f[static_cast<size_t>(col[kTime])]) + " goes back (before the previous line's)");
    first_data = false;
    PoseSample p;
    p.time_ps = time_ps;
    p.orientation = into_arpsim(q, layout.axes);
    out.push_back(p);
  }
  if (out.size() < 2) throw InputError(path, "", "the dataset has fewer than two samples");
  if (out.back().time_ps == out.front().time_ps) throw InputError(path, "", "every sample has the same timestamp: no motion in time");
  return out;
}

}  // namespace arp::tracker
