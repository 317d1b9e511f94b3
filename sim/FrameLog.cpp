#include "FrameLog.hpp"

#include <cerrno>
#include <cstring>

#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"
#include "common/StrictJson.hpp"

namespace arp::sim {

FrameLog::FrameLog(const std::string& csv_path, const std::string& report_path, const std::string& csv_header)
    : csv_path_(csv_path), report_path_(report_path) {
  if (!csv_path_.empty()) {
    csv_tmp_ = temp_path_beside(csv_path_);
    csv_.open(csv_tmp_, std::ios::binary);
    if (!(csv_ << csv_header)) throw InputError(csv_path_, "", "cannot write the file");
  }
  if (!report_path_.empty()) {
    rows_tmp_ = temp_path_beside(report_path_);
    rows_tmp_ += ".rows";
    rows_file_.open(rows_tmp_, std::ios::binary);
    if (!rows_file_) throw InputError(report_path_, "", "cannot write the file");
  }
}

FrameLog::~FrameLog() {
  if (csv_.is_open()) {
    csv_.close();
    discard_temp_file(csv_tmp_);
  }
  if (rows_file_.is_open()) rows_file_.close();
  if (!rows_tmp_.empty()) discard_temp_file(rows_tmp_);
}

void FrameLog::add(const nlohmann::json& row, const std::string& csv_row) {
  ++rows_;
  // (a stream keeps no reason of its own: errno, just after the write that failed, is kept)
  if (csv_.is_open()) {
    errno = 0;
    if (!(csv_ << csv_row) && csv_errno_ == 0) csv_errno_ = errno;
  }
  if (rows_file_.is_open()) {
    errno = 0;
    if (!(rows_file_ << dump_json(row) << '\n') && rows_errno_ == 0) rows_errno_ = errno;
  }
}

namespace {
// Why a stream's write failed: the errno kept at its first failed write, or its close's.
std::string reason(int kept) {
  const int e = kept != 0 ? kept : errno;
  return e != 0 ? std::string(": ") + std::strerror(e) : std::string();
}
}  // namespace

void FrameLog::finish(const nlohmann::json& report) {
  // Both files written before either is moved into place: a failure leaves neither, nor a temporary file.
  OutputGroup outputs;
  if (csv_.is_open()) {
    errno = 0;
    csv_.close();
    outputs.adopt(csv_tmp_, csv_path_);  // (removed with the group if anything below fails)
    if (!csv_) throw InputError(csv_path_, "", "cannot write the file" + reason(csv_errno_));
  }
  if (rows_file_.is_open()) {
    errno = 0;
    rows_file_.close();
    if (!rows_file_) throw InputError(report_path_, "", "cannot write the file (its frames' rows)" + reason(rows_errno_));
    const std::filesystem::path tmp = outputs.stage(report_path_);
    std::ofstream out(tmp, std::ios::binary);
    errno = 0;  // (from here, the first failed write's reason stays: nothing below fails otherwise)
    // The report's other keys, then "frames": one row per line, read back from the temporary file.
    const std::string head = dump_json(report, 2);  // "{\n  ...\n}" (or "{}")
    out << (report.empty() ? std::string("{") : head.substr(0, head.size() - 2) + ",") << "\n  \"frames\": [";
    std::ifstream in(rows_tmp_, std::ios::binary);
    std::string line;
    for (int64_t i = 0; std::getline(in, line); ++i) out << (i ? ",\n    " : "\n    ") << line;
    out << (rows_ ? "\n  " : "") << "]\n}\n";
    out.close();
    const int closed_errno = errno;
    in.close();
    discard_temp_file(rows_tmp_);  // (read: its rows are in the report, or the report failed)
    rows_tmp_.clear();
    errno = closed_errno;
    if (!out) throw InputError(report_path_, "", "cannot write the file" + reason(0));
  }
  outputs.commit();
}

}  // namespace arp::sim
