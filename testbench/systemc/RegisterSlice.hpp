// An example of adding a stage: one more pipeline register, passing the
// cube addresses through unchanged one clock later. The stage is a class owning its
// register (stage::RegisteredStage with latency 1); the module wraps it with
// ports named for what they carry. Putting it into a pipeline is one more
// type in a StageList (AddStageBench.cpp); docs/architecture.md walks
// through the same steps.
#pragma once
#include "rtl_model/stages/RegisteredStage.hpp"
#include "rtl_model/systemc/StageModule.hpp"

namespace arp::bench {

inline constexpr stage::StageInfo kAddressRegisterSliceInfo{-1, "address_register_slice", "cube_addresses",
                                                            "registered_addresses", {"face", "texel_x", "texel_y"}};

// Between the cube-face address generator and the display memories.
class AddressRegisterSliceStage : public stage::RegisteredStage<AddressRegisterSliceStage, stage::AddressToken,
                                                                stage::AddressToken, kAddressRegisterSliceInfo> {
 public:
  explicit AddressRegisterSliceStage(const stage::StageContext&) : RegisteredStage(1) {}
  void compute(const stage::AddressToken& t, stage::AddressToken& o) const { stage::copy_token(o, t); }
  // Not a configured stage: one clock, no configuration key.
  static dp::ScheduledStage scheduled(const dp::ArpConfig&) { return {1, -1}; }
};

using AddressRegisterSlice = scm::StageModule<AddressRegisterSliceStage>;

}  // namespace arp::bench
