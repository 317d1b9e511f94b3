// An example of adding a stage: one more pipeline register, passing any
// token through unchanged one clock later. The stage is a class owning its
// register (stage::RegisteredStage with latency 1); the module wraps it with
// ports named for what they carry. Putting it into a pipeline is one more
// type in a StageList (AddStageBench.cpp); docs/architecture.md walks
// through the same steps.
#pragma once
#include "rtl_model/stages/RegisteredStage.hpp"
#include "rtl_model/systemc/StageModule.hpp"

namespace arp::bench {

template <class T>
class RegisterSliceStage : public stage::RegisteredStage<T, T> {
 public:
  explicit RegisterSliceStage(const stage::StageContext&) : stage::RegisteredStage<T, T>(1) {}
  template <class InFifo, class OutFifo>
  void tick(int64_t cycle, InFifo& in, OutFifo& out) {
    this->tick_with(cycle, in, out, [](const T& t, T& o) { stage::copy_token(o, t); });
  }
};

// Between the cube-face address generator and the display memories.
class AddressRegisterSlice : public scm::StageModule<RegisterSliceStage<stage::AddressToken>> {
 public:
  static constexpr const char* kInput = "cube_addresses", *kOutput = "registered_addresses";
  static constexpr const char* kInstance = "address_register_slice";
  AddressRegisterSlice(sc_core::sc_module_name name, const stage::StageContext& ctx)
      : StageModule(name, ctx, kInput, kOutput, {"face", "texel_x", "texel_y"}) {}
  // Not a configured stage: one clock, no configuration key.
  static dp::ScheduledStage scheduled(const dp::ArpConfig&) { return {1, -1}; }
};

}  // namespace arp::bench
