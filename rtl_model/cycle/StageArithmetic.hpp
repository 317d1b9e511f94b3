// Each stage's arithmetic on a token: nothing but calls of the datapath
// functions (rtl_model/datapath), shared by the detailed, fast and loosely
// timed models so that one arithmetic runs under every timing.
#pragma once
#include <vector>

#include "PixelTokens.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::cycle {

class StageArithmetic {
 public:
  explicit StageArithmetic(const dp::ArpConfig& c);

  const dp::ArpConfig& config() const { return cfg_; }
  const dp::LensVectorTable& lens_table() const { return lens_; }
  const dp::HmdScanOut& scan_out() const { return scan_; }

  // Each stage fills its output token in place (tokens are large; no copies).
  void lens(const PixelSlot& s, LensToken& t) const {
    t.slot = s;
    for (int k = 0; k < s.eye_count; ++k) t.view[k] = lens_.at(s.eye_first + k, s.x, s.y);
  }
  void rotate(const LensToken& in, const dp::Mat3q& m, uint32_t sample, RotatedToken& t) const {
    t.slot = in.slot;
    t.sample = sample;
    for (int k = 0; k < in.slot.eye_count; ++k) t.world[k] = dp::rotate(m, in.view[k], rot_);
  }
  void address(const RotatedToken& in, AddressToken& t) const {
    t.slot = in.slot;
    t.sample = in.sample;
    for (int k = 0; k < in.slot.eye_count; ++k) t.address[k] = dp::generate_address(in.world[k], addr_, memo_ptr_);
  }
  void fetch(const AddressToken& in, const dp::DisplayMemorySet& mem, FetchToken& t) const;
  void compose(const FetchToken& in, ComposedToken& t) const {
    t.slot = in.slot;
    t.sample = in.sample;
    const int taps = bilinear_ ? 4 : 1;
    for (int k = 0; k < in.slot.eye_count; ++k) {
      t.wx[k] = in.wx[k];
      t.wy[k] = in.wy[k];
      for (int i = 0; i < taps; ++i) t.tap_color[k][i] = dp::compose(in.words[k][i], cfg_.memory.count, comp_).color;
    }
  }
  void filter(const ComposedToken& in, ColorToken& t) const {
    t.slot = in.slot;
    t.sample = in.sample;
    for (int k = 0; k < in.slot.eye_count; ++k) {
      const uint32_t* c = in.tap_color[k];
      t.color[k] = bilinear_ ? dp::bilinear_blend(c[0], c[1], c[2], c[3], in.wx[k], in.wy[k], cfg_.widths.texel_frac,
                                                   layout_)
                             : c[0];
    }
  }
  uint32_t display(uint32_t color) const { return scan_.to_display(color); }
  dp::Mat3q matrix(const dp::Quat& q) const { return dp::quantise_rotation(q, cfg_.widths.mat_frac); }

 private:
  dp::ArpConfig cfg_;
  dp::LensVectorTable lens_;
  dp::RotateParams rot_;
  dp::AddressGeneratorParams addr_;
  dp::MemoryFormat fmt_;
  dp::CompositionParams comp_;
  dp::ChannelLayout layout_;
  dp::HmdScanOut scan_;
  bool bilinear_;
  std::vector<uint32_t> memo_;           // dp::tabulate_aligned_reciprocal
  const uint32_t* memo_ptr_ = nullptr;
};

}  // namespace arp::cycle
