#include "DatasetImport.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "common/InputError.hpp"
#include "common/InputFile.hpp"

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

bool parse_axes(const std::string& s, DatasetLayout::Axes& out) {
  if (s == "gl") out = DatasetLayout::Axes::OpenGl;
  else if (s == "unity") out = DatasetLayout::Axes::Unity;
  else return false;
  return true;
}

namespace {

bool number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

}  // namespace

std::vector<PoseSample> read_head_motion_dataset(const std::string& path, const DatasetLayout& layout) {
  const auto in = open_input_stream(path, "dataset file");
  LineReader lines(*in, path);
  double to_ps = 1e12;
  switch (layout.time_unit) {
    case DatasetLayout::TimeUnit::Seconds: to_ps = 1e12; break;
    case DatasetLayout::TimeUnit::Milliseconds: to_ps = 1e9; break;
    case DatasetLayout::TimeUnit::Microseconds: to_ps = 1e6; break;
    case DatasetLayout::TimeUnit::Nanoseconds: to_ps = 1e3; break;
  }
  std::vector<PoseSample> out;
  std::string line;
  bool first_data = true, header_allowed = true;
  double t0 = 0;
  while (lines.next(line)) {
    const std::string where = lines.where();
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream ss(line);
    std::vector<std::string> f;
    for (std::string w; ss >> w;) f.push_back(w);
    if (f.empty() || f[0][0] == '#') continue;
    double probe;
    if (header_allowed && !number(f[0], probe)) {  // one header line, e.g. "timestamp frameId w x y z"
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (f.size() != 6)
      throw InputError(path, where, "expected 6 columns (timestamp frameId " + std::string(layout.scalar_last ? "x y z w" : "w x y z") +
                                        "), found " + std::to_string(f.size()));
    double v[6];
    static const char* kNames[6] = {"timestamp", "frameId", "quaternion", "quaternion", "quaternion", "quaternion"};
    for (int i = 0; i < 6; ++i)
      if (!number(f[static_cast<size_t>(i)], v[i]))
        throw InputError(path, where, std::string(kNames[i]) + " '" + quoted(f[static_cast<size_t>(i)]) + "' is not a finite number");
    if (v[1] != std::floor(v[1]) || v[1] < 0) throw InputError(path, where, "frameId '" + quoted(f[1]) + "' is not a non-negative integer");
    double w = v[2], x = v[3], y = v[4], z = v[5];
    if (layout.scalar_last) {
      x = v[2];
      y = v[3];
      z = v[4];
      w = v[5];
    }
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    if (n == 0) throw InputError(path, where, "the quaternion is zero");
    if (std::abs(n - 1) > 1e-2) throw InputError(path, where, "the quaternion is not unit length (norm " + std::to_string(n) + ")");
    if (layout.axes == DatasetLayout::Axes::Unity) {  // mirror through z = 0 into the right-handed frame
      x = 0.0 - x;  // (0 - 0 is +0: no "-0" in the trace)
      y = 0.0 - y;
    }
    if (first_data) t0 = v[0];
    const double t_ps = (v[0] - t0) * to_ps;
    if (!first_data && t_ps <= static_cast<double>(out.back().time_ps))
      throw InputError(path, where, "timestamp " + quoted(f[0]) + " does not come after the previous one");
    if (std::abs(t_ps) > 9e18) throw InputError(path, where, "timestamp out of range for the time unit");
    first_data = false;
    PoseSample p;
    p.time_ps = static_cast<int64_t>(std::llround(t_ps));
    p.orientation = glm::dquat(w / n, x / n, y / n, z / n);
    out.push_back(p);
  }
  if (out.size() < 2) throw InputError(path, "", "the dataset has fewer than two samples");
  return out;
}

}  // namespace arp::tracker
