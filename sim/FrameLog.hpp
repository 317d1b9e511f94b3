// A run's per-frame rows, streamed to their files as each frame is scanned
// out -- never held in memory, so a run's footprint does not grow with its
// length. The CSV goes to a temporary file beside its target; the report's
// "frames" array to a temporary file of JSON rows that the report writer
// splices in. Nothing reaches a target path until the run is finished (or
// interrupted: finish() then still writes what was done).
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace arp::sim {

class FrameLog {
 public:
  // Empty paths: that output is not written (and nothing is kept for it).
  FrameLog(const std::string& csv_path, const std::string& report_path, const std::string& csv_header);
  ~FrameLog();  // removes temporaries of an unfinished log
  FrameLog(const FrameLog&) = delete;
  FrameLog& operator=(const FrameLog&) = delete;

  void add(const nlohmann::json& row, const std::string& csv_row);
  int64_t rows() const { return rows_; }
  // Commits the CSV and writes the report: `report` with the rows as its "frames" array.
  void finish(const nlohmann::json& report);

 private:
  std::string csv_path_, report_path_;
  std::filesystem::path csv_tmp_, rows_tmp_;
  std::ofstream csv_, rows_file_;
  int64_t rows_ = 0;
  int csv_errno_ = 0, rows_errno_ = 0;  // the system's reason at each stream's first failed write (0: none)
};

}  // namespace arp::sim
