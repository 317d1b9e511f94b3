// Cube-face address generator: major axis and face (OpenGL table, documented
// tie rule), the reciprocal unit (table + Newton-Raphson, or the exact
// divider), face coordinates and the texel address with its sub-texel bits;
// timed.address_latency clocks.
#pragma once
#include <vector>

#include "RegisteredStage.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"

namespace arp::stage {

class AddressStage : public RegisteredStage<AddressStage, RotatedToken, AddressToken, kAddressInfo> {
 public:
  explicit AddressStage(const StageContext& ctx);

  void compute(const RotatedToken& in, AddressToken& t) const {
    for_each_eye(in, t, [&](int k) { t.address[k] = dp::generate_address(in.world[k], addr_, memo_ptr_); });
  }

 private:
  dp::AddressGeneratorParams addr_;
  std::vector<uint32_t> memo_;  // dp::tabulate_aligned_reciprocal: the reciprocal unit over its whole domain
  const uint32_t* memo_ptr_ = nullptr;
};

}  // namespace arp::stage
