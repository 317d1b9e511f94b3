#include "FrameLog.hpp"

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
  if (csv_.is_open()) csv_ << csv_row;
  if (rows_file_.is_open()) rows_file_ << dump_json(row) << '\n';
}

void FrameLog::finish(const nlohmann::json& report) {
  // Both files written before either is moved into place: a failure leaves neither, nor a temporary file.
  OutputGroup outputs;
  if (csv_.is_open()) {
    csv_.close();
    outputs.adopt(csv_tmp_, csv_path_);  // (removed with the group if anything below fails)
    if (!csv_) throw InputError(csv_path_, "", "cannot write the file");
  }
  if (rows_file_.is_open()) {
    rows_file_.close();
    if (!rows_file_) throw InputError(report_path_, "", "cannot write the file (its frames' rows)");
    const std::filesystem::path tmp = outputs.stage(report_path_);
    std::ofstream out(tmp, std::ios::binary);
    // The report's other keys, then "frames": one row per line, read back from the temporary file.
    const std::string head = dump_json(report, 2);  // "{\n  ...\n}" (or "{}")
    out << (report.empty() ? std::string("{") : head.substr(0, head.size() - 2) + ",") << "\n  \"frames\": [";
    std::ifstream in(rows_tmp_, std::ios::binary);
    std::string line;
    for (int64_t i = 0; std::getline(in, line); ++i) out << (i ? ",\n    " : "\n    ") << line;
    out << (rows_ ? "\n  " : "") << "]\n}\n";
    out.close();
    in.close();
    discard_temp_file(rows_tmp_);  // (read: its rows are in the report, or the report failed)
    rows_tmp_.clear();
    if (!out) throw InputError(report_path_, "", "cannot write the file");
  }
  outputs.commit();
}

}  // namespace arp::sim
