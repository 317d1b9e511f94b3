// What a run (`arpsim run --live usb`) or the live loop (`arpsim live`) takes
// from a live pose source, kept in one place: fixed against the run's timeline
// at its start (live_start), appended to the orientation stream in order,
// written as taken (--record-live: a trace that replays the run with --trace)
// and counted, so both consumers take, record and account alike.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "tracker/PoseSample.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::sim {

// --record-live records live input: refused (InputError naming it) when given without a live source.
void check_record_live(const std::string& record_path, bool live);

class LiveIntake {
 public:
  // record_path empty: nothing recorded. The trace is opened now, so a path that cannot be written is
  // said before any work (InputError naming it).
  LiveIntake(tracker::PoseSource& source, const std::string& record_path);
  ~LiveIntake();
  LiveIntake(const LiveIntake&) = delete;
  LiveIntake& operator=(const LiveIntake&) = delete;

  // At the run's start (start_ps on its timeline): fixes the source's time against it and takes the
  // pose at the start: the last sample received (live_start), or with nothing received the pose the
  // stream holds there. So a recording always begins at the start.
  void start(dp::OrientationStream& stream, int64_t start_ps, const std::string& stream_source);
  // Takes what has arrived: appended in time order, and recorded as the stream holds it (normalised).
  // A sample earlier than the stream's last is not taken: counted as received before the start when its
  // time is before the run's start (a report's older samples, handed over after the start), else as out of
  // order (a source whose times step back). After start().
  void take(dp::OrientationStream& stream, const std::vector<tracker::PoseSample>& got, const std::string& stream_source);

  // The samples taken, the pose at the start included.
  int64_t taken() const { return taken_; }
  int64_t before_start() const { return before_start_; }
  int64_t out_of_order() const { return out_of_order_; }
  bool recording() const { return record_ != nullptr; }
  int64_t recorded() const;
  // Writes the recording in place (temporary file, then rename); without a call nothing is left behind.
  void commit_record();

 private:
  tracker::PoseSource& source_;
  std::unique_ptr<tracker::TraceWriter> record_;
  int64_t offset_ps_ = 0, start_ps_ = 0, taken_ = 0, before_start_ = 0, out_of_order_ = 0;
  bool started_ = false;
  std::vector<tracker::PoseSample> appended_;
};

}  // namespace arp::sim
