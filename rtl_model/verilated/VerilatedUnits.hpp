// The verilated RTL modules as stage arithmetic: each unit streams a batch of
// tokens through its Verilator model (valid every clock, output always taken)
// and returns the outputs in order. A unit is built for one width
// configuration; make_units picks, for each module, the build whose
// parameters equal the configuration's (latencies aside: they move tokens in
// time, not their values) and refuses a configuration no build matches,
// naming the module, the parameter and the configurations built.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::vl {

class RotateUnit {
 public:
  virtual ~RotateUnit() = default;
  // out[i] = M[i] v[i]
  virtual void run(const dp::Mat3q* m, const dp::Vec3q* v, size_t n, dp::Vec3q* out) = 0;
};

class AddressUnit {
 public:
  virtual ~AddressUnit() = default;
  // face and texel-space position (Q.texel_frac) of each rotated vector
  virtual void run(const dp::Vec3q* r, size_t n, int32_t* face, int64_t* u, int64_t* v) = 0;
};

class ComposeUnit {
 public:
  virtual ~ComposeUnit() = default;
  // words: n groups of `memories` texel words (memory 0 first)
  virtual void run(const uint64_t* words, size_t n, dp::Composite* out) = 0;
};

class FilterUnit {
 public:
  virtual ~FilterUnit() = default;
  // taps: n groups of four composited colours (00, 10, 01, 11)
  virtual void run(const uint32_t* taps, const uint32_t* wx, const uint32_t* wy, size_t n, uint32_t* out) = 0;
};

struct Units {
  std::unique_ptr<RotateUnit> rotate;
  std::unique_ptr<AddressUnit> address;
  std::unique_ptr<ComposeUnit> compose;
  std::unique_ptr<FilterUnit> filter;  // null when pipeline.aa is off
  std::string configuration;           // the width configuration of the address generator's build
};

// Whether this build has the verilated models (Verilator was found), and why not.
bool verilated_available();
std::string verilated_unavailable_reason();
// The names of the width configurations built (rtl_model/hdl/configurations.txt).
std::vector<std::string> built_configurations();

// InputError("configuration", key, reason) when no build matches or the models are absent.
Units make_units(const dp::ArpConfig& c);

}  // namespace arp::vl
