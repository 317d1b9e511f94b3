// Functional model: whole HMD frames from the display memories and a stream
// of timed orientations, untimed and fast, calling only the datapath
// functions. It says what the hardware computes, bit for bit.
#pragma once
#include <cstdint>
#include <vector>

#include "rtl_model/datapath/HmdFrame.hpp"
#include "LinePasses.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/PipelineSchedule.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp {

struct RenderOptions {
  int threads = 0;            // 0: all hardware threads
  bool photon_times = false;  // fill HmdFrame::photon_ps
};

// A run of a scanline's pixels that latch the same orientation sample.
struct LatchSegment {
  int x0, x1;     // [x0, x1)
  size_t sample;  // orientation sample in the register for these pixels
};
// Splits scanline y of an eye into such runs, by LatchRule::sample (only the per-pixel latch makes more
// than one); the sample never decreases along a line, so each boundary is found by bisection.
void latch_segments(const dp::LatchRule& rule, const dp::OrientationStream& o, int64_t frame, int eye, int y, int width,
                    std::vector<LatchSegment>& out);

class FunctionalModel {
 public:
  // Validates the configuration; InputError("configuration", key, reason) on the first violation.
  explicit FunctionalModel(const dp::ArpConfig& cfg);

  const dp::ArpConfig& config() const { return cfg_; }
  const dp::VideoTiming& timing() const { return timing_; }
  // Whether the rotation and the address generator run in 32-bit lanes for this configuration
  // (dp::rotate_fits_int32, dp::address_fits_int32): the same results, twice the pixels per vector.
  bool rotates_in_32_bits() const { return rotate_int32_; }
  bool addresses_in_32_bits() const { return memo_view_.int32_lanes; }
  const dp::LensVectorTable& lens() const { return lens_; }
  const dp::AddressGeneratorParams& address_params() const { return addr_; }
  const dp::RotateParams& rotate_params() const { return rot_; }
  // Which tracker sample each pixel sees (its lead: dp::PipelineSchedule::orientation_lead).
  const dp::LatchRule& latch_rule() const { return latch_; }
  int64_t orientation_lead() const { return latch_.lead_cycles(); }

  // Renders frame `frame` (its timing decides which orientation samples
  // apply). The memory set must have this configuration's eyes, count and format.
  void render(const dp::DisplayMemorySet& mem, const dp::OrientationStream& orientation, int64_t frame,
              HmdFrame& out, const RenderOptions& opt = {}) const;

  // What render() reads an eye's memories through: the memories holding anything, each with its tile
  // pointers flattened over the six faces (kept in `flat`), and whether every one has its tiles in table
  // order (EyeSources::dense: the several-memory passes then place texels by arithmetic).
  static passes::EyeSources eye_sources(const dp::DisplayMemorySet& mem, int eye,
                                        std::vector<std::vector<int32_t>>& flat);

 private:
  template <dp::DividerKind D, dp::AaMode A>
  void render_impl(const dp::DisplayMemorySet& mem, const dp::OrientationStream& orientation, int64_t frame,
                   HmdFrame& out, const RenderOptions& opt) const;

  dp::ArpConfig cfg_;
  dp::VideoTiming timing_;
  dp::LensVectorTable lens_;
  dp::AddressGeneratorParams addr_;
  dp::RotateParams rot_;
  dp::MemoryFormat fmt_;
  dp::CompositionParams comp_;
  dp::ChannelLayout layout_;
  dp::HmdScanOut scan_;
  dp::LatchRule latch_;
  // dp::reciprocal tabulated over its whole input domain (see LinePasses.hpp).
  std::vector<uint32_t> memo_;  // the aligned reciprocal of every |ma|
  passes::ReciprocalMemo memo_view_;
  bool rotate_int32_ = false;  // dp::rotate_fits_int32 for this configuration and lens table
};

}  // namespace arp
