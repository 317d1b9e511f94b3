#include "PoseSource.hpp"

#include <cstdio>

#include "TraceFile.hpp"
#include "common/InputError.hpp"

namespace arp::tracker {

namespace {

class RecordedSource : public PoseSource {
 public:
  RecordedSource(std::vector<PoseSample> s, std::string name) : samples_(std::move(s)), name_(std::move(name)) {}
  std::string describe() const override { return name_; }
  bool live() const override { return false; }
  void poll(std::vector<PoseSample>& out, int) override {
    if (given_) return;
    out.insert(out.end(), samples_.begin(), samples_.end());
    given_ = true;
  }
  int64_t now_ps() const override { return 0; }
  std::vector<std::string> take_events() override { return {}; }

 private:
  std::vector<PoseSample> samples_;
  std::string name_;
  bool given_ = false;
};

class UsbSource : public PoseSource {
 public:
  explicit UsbSource(const RiftStreamOptions& o) : stream_(o) {}
  bool open(std::string& error) { return stream_.open(error); }
  bool choice_refused() const { return stream_.choice_refused(); }
  std::string describe() const override {
    return stream_.model() == RiftModel::DK1 ? "Oculus Rift DK1 (USB)" : "Oculus Rift DK2 (USB)";
  }
  bool live() const override { return true; }
  void poll(std::vector<PoseSample>& out, int timeout_ms) override { stream_.poll(timeout_ms, out); }
  int64_t now_ps() const override { return stream_.now_ps(); }
  std::vector<std::string> take_events() override {
    std::vector<std::string> lines;
    char at[32];
    for (const auto& e : stream_.take_events()) {
      std::snprintf(at, sizeof at, "[%.3f s] ", e.at_s);
      lines.push_back(at + std::string(to_string(e.kind)) + ": " + e.detail);
    }
    return lines;
  }
  bool usb_stats(StreamStats& out) const override {
    out = stream_.stats();
    return true;
  }
  bool connected() const override { return stream_.connected(); }

 private:
  RiftStream stream_;
};

}  // namespace

std::unique_ptr<PoseSource> recorded_source(std::vector<PoseSample> samples, std::string name) {
  return std::make_unique<RecordedSource>(std::move(samples), std::move(name));
}

std::unique_ptr<PoseSource> trace_file_source(const std::string& path) { return recorded_source(read_trace_csv(path), path); }

std::unique_ptr<PoseSource> dataset_source(const std::string& path, const DatasetLayout& layout) {
  return recorded_source(read_head_motion_dataset(path, layout), path);
}

RiftStreamOptions TrackerChoice::stream_options() const {
  if (mag_calibrate && !(mag_yaw_gain > 0))
    throw InputError("--mag-calibrate", "", "calibrates the magnetometer for --mag-yaw; give --mag-yaw GAIN too");
  RiftStreamOptions o;
  o.device = device;
  o.fusion.yaw_gain = mag_yaw_gain;
  o.fusion.mag_calibrate = mag_calibrate;
  return o;
}

std::unique_ptr<PoseSource> live_source(const std::string& live, const TrackerChoice& choice) {
  if (live.empty()) {
    if (!choice.device.empty()) throw InputError("--device", choice.device, "chooses the tracker of --live usb; give --live usb too");
    if (choice.mag_yaw_gain != 0) throw InputError("--mag-yaw", "", "corrects the yaw of --live usb; give --live usb too");
    if (choice.mag_calibrate) throw InputError("--mag-calibrate", "", "calibrates the magnetometer of --live usb; give --live usb too");
    return nullptr;
  }
  if (live != "usb") throw InputError("--live", live, "the live source is usb (an Oculus Rift DK1/DK2)");
  std::string err;
  bool bad_choice = false;
  auto s = usb_source(err, choice.stream_options(), &bad_choice);
  if (!s) throw InputError(bad_choice ? "--device" : "--live usb", bad_choice ? choice.device : "", err);
  return s;
}

std::unique_ptr<PoseSource> usb_source(std::string& error, const RiftStreamOptions& options, bool* choice_refused) {
  auto s = std::make_unique<UsbSource>(options);
  if (choice_refused) *choice_refused = false;
  if (!s->open(error)) {
    if (choice_refused) *choice_refused = s->choice_refused();
    return nullptr;
  }
  return s;
}

}  // namespace arp::tracker
