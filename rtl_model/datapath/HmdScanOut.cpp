#include "HmdScanOut.hpp"

namespace arp::dp {

HmdScanOut::HmdScanOut(const MemoryFormat& f, const PipelineConfig& p)
    : bits_(p.display_bits),
      identity_(f.red_bits == p.display_bits && f.green_bits == p.display_bits && f.blue_bits == p.display_bits),
      sh_{f.green_bits + f.blue_bits, f.blue_bits, 0},
      mk_{(1u << f.red_bits) - 1, (1u << f.green_bits) - 1, (1u << f.blue_bits) - 1} {
  const uint64_t dmax = (uint64_t{1} << bits_) - 1;
  for (int c = 0; c < 3; ++c) {
    const uint64_t smax = mk_[c];
    lut_[c].resize(smax + 1);
    for (uint64_t v = 0; v <= smax; ++v) lut_[c][v] = static_cast<uint32_t>((v * dmax * 2 + smax) / (2 * smax));
  }
}

}  // namespace arp::dp
