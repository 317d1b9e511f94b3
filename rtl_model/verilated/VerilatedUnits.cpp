#include "VerilatedUnits.hpp"

#include <sstream>
#include <stdexcept>

#include "common/InputError.hpp"
#include "rtl_model/verilated/HdlConfig.hpp"

#ifdef ARPSIM_HAVE_VERILATED
#include "rtl_model/hdl/HdlModels.hpp"
#include "rtl_model/verilated/PortBits.hpp"
#endif

namespace arp::vl {

#ifdef ARPSIM_HAVE_VERILATED
namespace {

// A verilated module driven as a stream: an input every clock while any is
// left, the output always taken, so tokens leave in order LATENCY clocks
// after they entered.
template <class Top>
class Stream {
 public:
  Stream() {
    top_.clk = 0;
    top_.rst_n = 0;
    top_.in_valid = 0;
    top_.out_ready = 1;
    top_.eval();
    tick();
    tick();
    top_.rst_n = 1;
  }
  template <class Put, class Take>
  void run(size_t n, const Put& put, const Take& take) {
    size_t next = 0, done = 0;
    const size_t limit = n + 1000;  // clocks: a module of latency below 1000 drains within them
    for (size_t cycle = 0; done < n; ++cycle) {
      if (cycle > limit) throw std::logic_error("verilated module stalled: " + std::to_string(done) + " of " + std::to_string(n));
      top_.in_valid = next < n;
      if (next < n) put(top_, next);
      top_.out_ready = 1;
      top_.eval();
      if (top_.out_valid) take(top_, done++);
      const bool accepted = next < n && top_.in_ready;
      tick();
      if (accepted) ++next;
    }
    top_.in_valid = 0;
  }

 private:
  void tick() {
    top_.clk = 1;
    top_.eval();
    top_.clk = 0;
    top_.eval();
  }
  Top top_;
};

template <class Top>
class RotateImpl final : public RotateUnit {
 public:
  explicit RotateImpl(const HdlConfig& c) : mw_(c.mat_frac + 2), vw_(c.vec_frac + 2), rw_(c.rot_frac + 2) {}
  void run(const dp::Mat3q* m, const dp::Vec3q* v, size_t n, dp::Vec3q* out) override {
    s_.run(
        n,
        [&](Top& t, size_t i) {
          for (int k = 0; k < 9; ++k) put_field(t.in_matrix, k * mw_, mw_, m[i].m[k]);
          put_vector(t.in_vector, vw_, v[i]);
        },
        [&](const Top& t, size_t i) {
          out[i] = get_vector<dp::Vec3q>(t.out_vector, rw_);
        });
  }

 private:
  int mw_, vw_, rw_;
  Stream<Top> s_;
};

template <class Top>
class AddressImpl final : public AddressUnit {
 public:
  explicit AddressImpl(const HdlConfig& c) : rw_(c.rot_frac + 2) {}
  void run(const dp::Vec3q* r, size_t n, int32_t* face, int64_t* u, int64_t* v) override {
    s_.run(
        n,
        [&](Top& t, size_t i) {
          put_vector(t.in_vector, rw_, r[i]);
        },
        [&](const Top& t, size_t i) {
          face[i] = static_cast<int32_t>(t.out_face);
          u[i] = static_cast<int64_t>(t.out_u);
          v[i] = static_cast<int64_t>(t.out_v);
        });
  }

 private:
  int rw_;
  Stream<Top> s_;
};

template <class Top>
class ComposeImpl final : public ComposeUnit {
 public:
  explicit ComposeImpl(const HdlConfig& c)
      : n_(c.memories), iw_(c.memories > 1 ? 64 - __builtin_clzll(static_cast<uint64_t>(c.memories - 1)) : 1),
        cb_(c.red_bits + c.green_bits + c.blue_bits), db_(c.depth_bits) {}
  void run(const uint64_t* words, size_t n, dp::Composite* out) override {
    s_.run(
        n,
        [&](Top& t, size_t i) {
          for (int k = 0; k < n_; ++k)
            put_field(t.in_texels, 64 * k, 64, static_cast<int64_t>(words[i * static_cast<size_t>(n_) + static_cast<size_t>(k)]));
        },
        [&](const Top& t, size_t i) {
          out[i].color = static_cast<uint32_t>(get_unsigned(t.out_color, 0, cb_));
          out[i].depth = static_cast<uint32_t>(get_unsigned(t.out_depth, 0, db_));
          out[i].memory = t.out_empty ? -1 : static_cast<int>(get_unsigned(t.out_memory, 0, iw_));
        });
  }

 private:
  int n_, iw_, cb_, db_;
  Stream<Top> s_;
};

template <class Top>
class FilterImpl final : public FilterUnit {
 public:
  explicit FilterImpl(const HdlConfig& c) : cb_(c.red_bits + c.green_bits + c.blue_bits) {}
  void run(const uint32_t* taps, const uint32_t* wx, const uint32_t* wy, size_t n, uint32_t* out) override {
    s_.run(
        n,
        [&](Top& t, size_t i) {
          for (int k = 0; k < 4; ++k) put_field(t.in_taps, k * cb_, cb_, taps[4 * i + static_cast<size_t>(k)]);
          put_field(t.in_wx, 0, 32, wx[i]);
          put_field(t.in_wy, 0, 32, wy[i]);
        },
        [&](const Top& t, size_t i) { out[i] = static_cast<uint32_t>(get_unsigned(t.out_color, 0, cb_)); });
  }

 private:
  int cb_;
  Stream<Top> s_;
};

// The builds of one module, and the choice among them.
struct Offers {
  std::string what;   // the module, for messages
  std::string names;  // its parameters, for messages
  std::ostringstream built;
  std::string chosen;
};

#define ARP_SAME(field) &&a.field == b.field
#define ARP_NAME(field) "/" #field
#define ARP_VALUE(field) << "/" << h.field

template <class Impl, class Unit>
void offer(std::unique_ptr<Unit>& slot, bool same, const HdlConfig& built, const char* config, const std::string& values,
           Offers& o) {
  o.built << (o.built.tellp() > 0 ? ", " : "") << values << " (" << config << ")";
  if (!slot && same) {
    slot = std::make_unique<Impl>(built);
    o.chosen = config;
  }
}

// A module's helpers: whether two configurations agree on its parameters,
// its values and names for messages, and the offer of one of its builds for
// its slot (impl) in Units.
#define ARP_MODULE_HELPERS(module, impl, slot)                                                                     \
  bool same_##module(const HdlConfig& a, const HdlConfig& b) { return true ARP_HDL_PARAMS_##module(ARP_SAME); }   \
  std::string values_##module(const HdlConfig& h) {                                                               \
    std::ostringstream s;                                                                                         \
    s ARP_HDL_PARAMS_##module(ARP_VALUE);                                                                         \
    return s.str().substr(1);                                                                                     \
  }                                                                                                               \
  std::string names_##module() { return std::string(ARP_HDL_PARAMS_##module(ARP_NAME)).substr(1); }             \
  template <class Top>                                                                                            \
  void offer_##module(Units& u, const HdlConfig& c, const char* config, const HdlConfig& want, Offers& o) {      \
    offer<impl<Top>>(u.slot, same_##module(c, want), c, config, values_##module(c), o);                           \
  }
ARP_MODULE_HELPERS(omu, RotateImpl, rotate)
ARP_MODULE_HELPERS(cfag, AddressImpl, address)
ARP_MODULE_HELPERS(comp, ComposeImpl, compose)
ARP_MODULE_HELPERS(filt, FilterImpl, filter)

}  // namespace

bool verilated_available() { return true; }
std::string verilated_unavailable_reason() { return ""; }

std::vector<std::string> built_configurations() {
  std::vector<std::string> names;
#define ARP_NAME_OF(module, config, mutant, cls, ...) \
  if (std::string(#module) == "cfag") names.push_back(#config);
  ARP_HDL_PRODUCT_MODELS(ARP_NAME_OF)
#undef ARP_NAME_OF
  return names;
}

Units make_units(const dp::ArpConfig& cfg) {
  const HdlConfig want = hdl_config_of(cfg);
  const bool bilinear = cfg.pipeline.aa == dp::AaMode::Bilinear;
  Units u;
  Offers offers_omu{"orientation matrix unit", names_omu(), {}, {}};
  Offers offers_cfag{"cube-face address generator", names_cfag(), {}, {}};
  Offers offers_comp{"composition unit", names_comp(), {}, {}};
  Offers offers_filt{"bilinear filter", names_filt(), {}, {}};
#define ARP_OFFER(module, config, mutant, cls, ...) \
  {                                                 \
    HdlConfig c{};                                  \
    (__VA_ARGS__);                                  \
    offer_##module<cls>(u, c, #config, want, offers_##module); \
  }
  ARP_HDL_PRODUCT_MODELS(ARP_OFFER)
#undef ARP_OFFER
  if (!bilinear) u.filter.reset();
  auto refuse = [&](const Offers& o, const std::string& values) {
    throw InputError("configuration", "--fidelity verilated",
                     "the " + o.what + "'s RTL is built for " + o.names + " = " + o.built.str() +
                         " (rtl_model/hdl/configurations.txt); this configuration has " + values +
                         ". Add it there and rebuild, or pick one of those.");
  };
  if (!u.rotate) refuse(offers_omu, values_omu(want));
  if (!u.address) refuse(offers_cfag, values_cfag(want));
  if (!u.compose) refuse(offers_comp, values_comp(want));
  if (bilinear && !u.filter) refuse(offers_filt, values_filt(want));
  u.configuration = offers_cfag.chosen;
  return u;
}

#else  // built without Verilator

bool verilated_available() { return false; }
std::string verilated_unavailable_reason() {
  return "this build has no verilated level: Verilator was not found when it was configured "
         "(scripts/setup.sh installs it; then configure and build again)";
}
std::vector<std::string> built_configurations() { return {}; }
Units make_units(const dp::ArpConfig&) {
  throw InputError("configuration", "--fidelity verilated", verilated_unavailable_reason());
}

#endif

}  // namespace arp::vl
