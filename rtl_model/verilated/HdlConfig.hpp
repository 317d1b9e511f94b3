// One width configuration of the RTL (rtl_model/hdl/configurations.txt): its
// parameters under their lower-case names, as the generated HdlModels.hpp
// assigns them, and what they mean to the datapath.
#pragma once
#include <cstdint>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::vl {

struct HdlConfig {
  int vec_frac, mat_frac, rot_frac, rot_rounding, divider, recip_index_bits, recip_frac_bits, newton_steps,
      quot_frac, div_rounding, texel_frac, texel_rounding, face_size, rotate_latency, address_latency;
  int memories, red_bits, green_bits, blue_bits, depth_bits, background, compose_latency, filter_latency;

  dp::DatapathWidths widths() const {
    dp::DatapathWidths w;
    w.vec_frac = vec_frac;
    w.mat_frac = mat_frac;
    w.rot_frac = rot_frac;
    w.rot_rounding = static_cast<dp::Rounding>(rot_rounding);
    w.divider = static_cast<dp::DividerKind>(divider);
    w.recip_index_bits = recip_index_bits;
    w.recip_frac_bits = recip_frac_bits;
    w.newton_steps = newton_steps;
    w.quot_frac = quot_frac;
    w.div_rounding = static_cast<dp::Rounding>(div_rounding);
    w.texel_frac = texel_frac;
    w.texel_rounding = static_cast<dp::Rounding>(texel_rounding);
    return w;
  }
  dp::MemoryFormat format() const {
    dp::MemoryFormat f;
    f.face_size = face_size;
    f.red_bits = red_bits;
    f.green_bits = green_bits;
    f.blue_bits = blue_bits;
    f.depth_bits = depth_bits;
    return f;
  }
};

// The configuration's values of the RTL parameters (latencies from timed.*).
HdlConfig hdl_config_of(const dp::ArpConfig& c);

}  // namespace arp::vl
