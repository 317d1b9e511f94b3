// Cube-face address generator: major axis and face (OpenGL table, documented
// tie rule), the reciprocal unit (table + Newton-Raphson, or the exact
// divider), face coordinates and the texel address with its sub-texel bits;
// timed.address_latency clocks.
#pragma once
#include <vector>

#include "RegisteredStage.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"

namespace arp::stage {

class AddressStage : public RegisteredStage<RotatedToken, AddressToken> {
 public:
  static constexpr dp::Stage kId = dp::Stage::Address;
  explicit AddressStage(const StageContext& ctx);

  template <class InFifo, class OutFifo>
  void tick(int64_t cycle, InFifo& in, OutFifo& out) {
    tick_with(cycle, in, out, [this](const RotatedToken& t, AddressToken& o) { compute(t, o); });
  }
  void compute(const RotatedToken& in, AddressToken& t) const {
    t.slot = in.slot;
    t.sample = in.sample;
    for (int k = 0; k < in.slot.eye_count; ++k) t.address[k] = dp::generate_address(in.world[k], addr_, memo_ptr_);
  }

 private:
  dp::AddressGeneratorParams addr_;
  std::vector<uint32_t> memo_;  // dp::tabulate_aligned_reciprocal: the reciprocal unit over its whole domain
  const uint32_t* memo_ptr_ = nullptr;
};

}  // namespace arp::stage
