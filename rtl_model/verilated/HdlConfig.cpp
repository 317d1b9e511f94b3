#include "HdlConfig.hpp"

namespace arp::vl {

HdlConfig hdl_config_of(const dp::ArpConfig& c) {
  const dp::DatapathWidths& w = c.widths;
  const dp::MemoryFormat f(c.memory);
  auto latency = [&](dp::Stage s) { return c.timed.stage[static_cast<size_t>(s)].latency_cycles; };
  HdlConfig h{};
  h.vec_frac = w.vec_frac;
  h.mat_frac = w.mat_frac;
  h.rot_frac = w.rot_frac;
  h.rot_rounding = static_cast<int>(w.rot_rounding);
  h.divider = static_cast<int>(w.divider);
  h.recip_index_bits = w.recip_index_bits;
  h.recip_frac_bits = w.recip_frac_bits;
  h.newton_steps = w.newton_steps;
  h.quot_frac = w.quot_frac;
  h.div_rounding = static_cast<int>(w.div_rounding);
  h.texel_frac = w.texel_frac;
  h.texel_rounding = static_cast<int>(w.texel_rounding);
  h.face_size = c.memory.face_size;
  h.rotate_latency = latency(dp::Stage::Rotate);
  h.address_latency = latency(dp::Stage::Address);
  h.memories = c.memory.count;
  h.red_bits = c.memory.red_bits;
  h.green_bits = c.memory.green_bits;
  h.blue_bits = c.memory.blue_bits;
  h.depth_bits = c.memory.depth_bits;
  h.background = static_cast<int>(f.pack_rgb8(c.memory.background[0], c.memory.background[1], c.memory.background[2]));
  h.compose_latency = latency(dp::Stage::Compose);
  h.filter_latency = latency(dp::Stage::Filter);
  return h;
}

}  // namespace arp::vl
