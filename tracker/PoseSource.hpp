// One interface for every head-motion source: recorded ones (a trace file, a
// public dataset, synthetic motion) hold all their samples from the start;
// live ones (a DK1/DK2 on USB) deliver samples as they arrive, on their own
// clock. Consumers -- `arpsim run --live`, `arpsim live`, `tracker record` --
// poll a source the same way whatever it is.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "DatasetImport.hpp"
#include "PoseSample.hpp"
#include "RiftStream.hpp"

namespace arp::tracker {

class PoseSource {
 public:
  virtual ~PoseSource() = default;
  virtual std::string describe() const = 0;
  // true: samples arrive in real time, timed on the source's clock (now_ps).
  virtual bool live() const = 0;
  // Appends the samples that became available since the last call (a
  // recorded source: all of them, on the first call). A live source handles
  // its device for up to timeout_ms.
  virtual void poll(std::vector<PoseSample>& out, int timeout_ms) = 0;
  // Now on the source's timeline; 0 for recorded sources.
  virtual int64_t now_ps() const = 0;
  // What happened since the last call (disconnects, malformed reports, ...), one line each.
  virtual std::vector<std::string> take_events() = 0;
  // The USB stream's counters, for live USB sources (false otherwise).
  virtual bool usb_stats(StreamStats&) const { return false; }
  virtual bool connected() const { return true; }
};

// Recorded sources. The samples are validated by whoever made them (trace and dataset readers throw InputError).
std::unique_ptr<PoseSource> recorded_source(std::vector<PoseSample> samples, std::string name);
std::unique_ptr<PoseSource> trace_file_source(const std::string& path);
std::unique_ptr<PoseSource> dataset_source(const std::string& path, const DatasetLayout& layout);
// The DK1/DK2 on USB that options.device names (or the only one); nullptr with the reason in `error`
// when it cannot be opened, and *choice_refused set when the reason is the choice (--device names
// none of the trackers attached, or several are attached and none was named) rather than the machine.
std::unique_ptr<PoseSource> usb_source(std::string& error, const RiftStreamOptions& options = {}, bool* choice_refused = nullptr);
// Which tracker and how its yaw is held: --device, --mag-yaw, --mag-calibrate (run, live, tracker record).
struct TrackerChoice {
  std::string device;          // its serial number or BUS:ADDR; empty: the only one attached
  double mag_yaw_gain = 0;     // the magnetometer's yaw correction, 1/s (0: off)
  bool mag_calibrate = false;  // learn the magnetometer's hard iron first (FusionParams::mag_calibrate)
  // The stream's options they set.
  RiftStreamOptions stream_options() const;
};
// What --live names ("usb"; empty: none, and then the choice must be empty too), opened: InputError naming
// the option and the reason otherwise.
std::unique_ptr<PoseSource> live_source(const std::string& live, const TrackerChoice& choice);

}  // namespace arp::tracker
