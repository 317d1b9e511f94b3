#include "TraceFile.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "common/AtomicFile.hpp"
#include "common/Units.hpp"
#include "common/InputError.hpp"
#include "common/InputFile.hpp"
#include "common/PrintfText.hpp"

namespace arp::tracker {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream ss(line);
  while (std::getline(ss, cur, ',')) out.push_back(cur);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

std::vector<PoseSample> read_trace_csv(const std::string& path, const TraceWindow& window) {
  const auto in = open_input_stream(path, "trace file");
  return read_trace_csv(*in, path, window);
}

std::vector<PoseSample> read_trace_csv(std::istream& in, const std::string& path, const TraceWindow& window) {
  LineReader lines(in, path);
  std::vector<PoseSample> out;
  std::string line;
  size_t columns = 0;
  bool any = false;  // a sample read, kept or not
  static const char* kNames[8] = {"time_s", "qw", "qx", "qy", "qz", "px", "py", "pz"};
  while (lines.next(line)) {
    const std::string t = trim_blanks(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = lines.where();
    auto fields = split(t);
    for (auto& f : fields) f = trim_blanks(f);
    if (columns == 0) {  // the header
      // A spreadsheet's UTF-8 byte-order mark is not part of the first name (and would not be seen in a message).
      if (!fields.empty() && fields[0].rfind("\xEF\xBB\xBF", 0) == 0) fields[0].erase(0, 3);
      if (t.find('\r') != std::string::npos)
        throw InputError(path, where, "lines end in a carriage return alone (CR, not LF or CR LF): save the file with LF line ends");
      if (fields.size() != 5 && fields.size() != 8)
        throw InputError(path, where, "header must be time_s,qw,qx,qy,qz or time_s,qw,qx,qy,qz,px,py,pz");
      for (size_t i = 0; i < fields.size(); ++i)
        if (fields[i] != kNames[i])
          throw InputError(path, where, "header column " + std::to_string(i + 1) + " is '" + quoted(fields[i]) + "', expected '" +
                                            kNames[i] + "'");
      columns = fields.size();
      continue;
    }
    if (fields.size() != columns)
      throw InputError(path, where, std::to_string(fields.size()) + " columns, the header has " + std::to_string(columns));
    double v[8];
    for (size_t i = 0; i < columns; ++i) {
      const char* s = fields[i].c_str();
      char* end = nullptr;
      errno = 0;
      v[i] = std::strtod(s, &end);
      if (fields[i].empty() || end == s || *end != '\0')
        throw InputError(path, where, std::string(kNames[i]) + " '" + quoted(fields[i]) + "' is not a number");
      if (fields[i].find_first_of("xX") != std::string::npos)  // (strtod reads C's hexadecimal numbers: 0x1 would be 1 s)
        throw InputError(path, where, std::string(kNames[i]) + " '" + quoted(fields[i]) + "' is not a decimal number");
      if (!std::isfinite(v[i]) || (errno == ERANGE && std::abs(v[i]) > 1.0))
        throw InputError(path, where, std::string(kNames[i]) + " '" + quoted(fields[i]) + "' is not a finite number");
    }
    if (std::abs(v[0]) > kPoseTimeLimitS)
      throw InputError(path, where, "time_s " + quoted(fields[0]) + " is outside +-" + pose_time_limit_text());
    const double n = std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (!(std::abs(n - 1.0) <= 1e-3))
      throw InputError(path, where, "quaternion has length " + std::to_string(n) + "; a rotation needs a unit quaternion");
    PoseSample p;
    p.time_ps = std::llround(v[0] * 1e12);
    p.orientation = glm::dquat(v[1] / n, v[2] / n, v[3] / n, v[4] / n);
    if (columns == 8) {
      for (size_t i = 5; i < 8; ++i)
        if (std::abs(v[i]) > kWorldLimitM)
          throw InputError(path, where, std::string(kNames[i]) + " " + quoted(fields[i]) + " is outside +-" +
                                            std::to_string(static_cast<int64_t>(kWorldLimitM)) + " m (the world's reach)");
      p.has_position = true;
      p.position = glm::dvec3(v[5], v[6], v[7]);
    }
    if (any && p.time_ps < (out.empty() ? p.time_ps : out.back().time_ps))
      throw InputError(path, where, "time " + quoted(fields[0]) + " s is earlier than the previous sample's");
    any = true;
    // The window: one sample before its start (the one held at the start), none but the first after its end.
    if (p.time_ps <= window.from_ps) out.clear();
    out.push_back(p);
    // Denser than any tracker: refused while still small (an endless stream of one time on standard input
    // would otherwise fill the memory before the window ends).
    // (in double: a trace may span +-9e6 s, more picoseconds than int64_t holds between its ends)
    const double span_s = (static_cast<double>(out.back().time_ps) - static_cast<double>(out.front().time_ps)) * 1e-12;
    if (static_cast<double>(out.size()) > kMaxSampleRateHz * (1.0 + span_s))
      throw InputError(path, where,
                       std::to_string(out.size()) + " samples within " + printf_text("%.6g", span_s) +
                           " s: more than " + printf_text("%.0f", kMaxSampleRateHz) + " a second, faster than any tracker");
    if (p.time_ps > window.to_ps) break;
  }
  if (columns == 0) throw InputError(path, "", "no header line (time_s,qw,qx,qy,qz[,px,py,pz])");
  if (out.empty()) throw InputError(path, "", "no samples after the header");
  return out;
}

void write_trace_csv(const std::string& path, const std::vector<PoseSample>& samples) {
  bool positions = !samples.empty();
  for (const auto& s : samples) positions = positions && s.has_position;
  TraceWriter w(path, positions);
  for (const auto& s : samples) w.append(s);
  w.commit();
}

TraceWriter::TraceWriter(const std::string& path, bool positions) : path_(path), positions_(positions) {
  tmp_ = temp_path_beside(path).string();
  f_ = std::fopen(tmp_.c_str(), "w");
  if (!f_) throw InputError(path, "", std::string("cannot write the trace file: ") + std::strerror(errno));
  errno = 0;
  ok_ = std::fprintf(f_, "# arpsim head-motion trace: seconds, unit quaternion w x y z (head -> world)%s\n",
                     positions ? ", position in metres" : "") > 0;
  ok_ = ok_ && std::fprintf(f_, positions ? "time_s,qw,qx,qy,qz,px,py,pz\n" : "time_s,qw,qx,qy,qz\n") > 0;
  if (!ok_) errno_ = errno;
}

TraceWriter::~TraceWriter() {
  if (!f_) return;
  std::fclose(f_);
  discard_temp_file(tmp_);
}

// Why a write failed: the errno of the first write that failed (kept), or of the close.
std::string TraceWriter::failure() {
  if (!ok_ && errno_ == 0) errno_ = errno;
  const int e = errno_ != 0 ? errno_ : errno;
  return e != 0 ? std::string(": ") + std::strerror(e) : std::string();
}

void TraceWriter::append(const PoseSample& s) {
  if (!f_) throw std::logic_error("trace already committed");
  if (written_ > 0 && s.time_ps < last_ps_) throw std::invalid_argument("trace samples out of time order");
  if (positions_ && !s.has_position) throw std::invalid_argument("a trace with positions needs one for every sample");
  const auto& q = s.orientation;
  ok_ = ok_ && std::fprintf(f_, "%.12f,%.17g,%.17g,%.17g,%.17g", static_cast<double>(s.time_ps) * 1e-12, q.w, q.x, q.y, q.z) > 0;
  if (positions_) ok_ = ok_ && std::fprintf(f_, ",%.17g,%.17g,%.17g", s.position.x, s.position.y, s.position.z) > 0;
  ok_ = ok_ && std::fputc('\n', f_) != EOF;
  if (!ok_) throw InputError(path_, "", "writing the trace failed" + failure());
  last_ps_ = s.time_ps;
  ++written_;
}

void TraceWriter::commit() {
  if (!f_) throw std::logic_error("trace already committed");
  if (ok_) errno = 0;
  const bool closed = std::fclose(f_) == 0;
  f_ = nullptr;
  if (!ok_ || !closed) {
    const std::string why = failure();
    discard_temp_file(tmp_);
    throw InputError(path_, "", "writing the trace failed" + why);
  }
  commit_temp_file(tmp_, path_);
}

}  // namespace arp::tracker
