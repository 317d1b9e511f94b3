// HMD scan-out: at each active slot the pixel for that slot must be at the
// head of its FIFO, taken timed.scanout_latency clocks early, converted to
// the panel's colour depth and shown at the slot (photon time = slot time +
// pipeline.photon_delay_ps). A missing pixel is an underflow (counted, and
// shown in the underflow colour); a pixel arriving after its slot is dropped
// and counted. Frames go to the sink after their last active slot, with the
// orientation-sample -> photon latency of their pixels. The stage keeps its
// own scan counters (ScanTiming), its delay line and the frame it assembles.
#pragma once
#include <cstdint>
#include <vector>

#include "FrameReport.hpp"
#include "ScanTiming.hpp"
#include "StageContext.hpp"
#include "StageInfo.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"

namespace arp::stage {

// Frames computed ahead of the clock (the fast level's speculation): where
// scan-out takes the colour of a pixel marked on_schedule.
class PrerenderedFrames {
 public:
  virtual ~PrerenderedFrames() = default;
  virtual const HmdFrame& frame(int64_t f) = 0;
  virtual void retire_before(int64_t f) = 0;
};

class ScanOutStage {
 public:
  using Input = ColorToken;
  using Output = void;
  static constexpr const StageInfo& kInfo = kScanOutInfo;
  static dp::ScheduledStage scheduled(const dp::ArpConfig& c) {
    return {c.timed.stage[static_cast<size_t>(kInfo.id)].latency_cycles, kInfo.id};
  }
  explicit ScanOutStage(const StageContext& ctx);

  int latency() const { return latency_; }
  bool idle() const { return true; }  // it holds no pixel between clocks: its delay line is the panel's
  template <class InFifo>
  void tick(int64_t cycle, InFifo& in) {
    // The panel side: the pixel taken latency cycles ago is shown now.
    const Shown& now = delay_[ring(cycle)];
    display_valid = now.valid;
    display_rgb = now.rgb;
    delay_[ring(cycle)] = Shown{};
    const int64_t slot = cycle + latency_;
    PixelSlot s;
    if (!scan_.decode(slot, s, cursor_)) {
      // Blanking: a pixel whose slot has passed is dropped, so a late pipeline catches up.
      if (in.can_read() && in.front().slot.slot_cycle < slot) {
        in.read(cycle);
        ++late_;
        ++late_total_;
      }
      return;
    }
    if (in.can_read() && in.front().slot.slot_cycle < slot) {
      in.read(cycle);  // late: its slot has passed
      ++late_;
      ++late_total_;
      underflow(s);
    } else if (in.can_read() && in.front().slot.slot_cycle == slot) {
      show(in.front(), slot);
      in.read(cycle);
    } else {
      underflow(s);
    }
    if (slot == scan_.last_slot(s.frame)) finish_frame(s.frame);
  }

  int64_t underflows() const { return underflows_total_; }
  int64_t late_discarded() const { return late_total_; }
  // The fast level: where on-schedule pixels take their colour from.
  void use_prerendered(PrerenderedFrames* p) { prerendered_ = p; }
  // Memory colour code -> the panel's.
  uint32_t to_display(uint32_t color) const { return panel_.to_display(color); }

  void set_probing(bool) {}  // its probes are always current
  template <class Fn>
  void for_each_probe(Fn&& fn) const {
    fn("display_valid", display_valid);
    fn("display_rgb", display_rgb);
    fn("underflows", underflow_count);
  }
  // Traced: the pixel on the panel this cycle (first eye) and the running underflow count.
  bool display_valid = false;
  uint32_t display_rgb = 0;
  int64_t underflow_count = 0;

 private:
  struct Shown {
    bool valid = false;
    uint32_t rgb = 0;
  };
  size_t ring(int64_t c) const {
    if (latency_ == 1) return 0;  // (the default: no divide)
    const int64_t m = c % latency_;
    return static_cast<size_t>(m < 0 ? m + latency_ : m);
  }
  void show(const ColorToken& t, int64_t slot);
  void underflow(const PixelSlot& s);
  void finish_frame(int64_t frame);

  ScanTiming scan_;
  dp::HmdScanOut panel_;
  const dp::OrientationStream& stream_;
  FrameSink sink_;
  int latency_;
  int64_t photon_delay_;
  std::vector<Shown> delay_;
  HmdFrame frame_;
  LatencyCollector lat_;
  int64_t underflows_ = 0, late_ = 0, underflows_total_ = 0, late_total_ = 0;
  uint32_t bad_;
  ScanTiming::Cursor cursor_;
  PrerenderedFrames* prerendered_ = nullptr;
  dp::ClockTimeCursor clock_;
};

}  // namespace arp::stage
