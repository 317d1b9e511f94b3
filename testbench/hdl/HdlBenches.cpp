// RTL benches: every verilated module of rtl_model/hdl (HdlModels.hpp, one
// class per module x width configuration x mutant) driven through its
// valid/ready ports with directed and seeded-random vectors, its outputs
// compared bit for bit with the datapath functions (rtl_model/datapath) and
// its latency in clocks with the configured value: exactly while the output
// is always taken, at least under random back-pressure. Each bench counts
// the directed cases it reached (functional coverage) and fails if one was
// never reached. A mutant (MUTANT != 0, a deliberate bug selected by one RTL
// parameter) must make its bench report a mismatch: the negative control.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fstream>
#include <set>

#include <verilated_cov.h>
#include <verilated_vcd_c.h>

#include "rtl_model/hdl/HdlModels.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/verilated/HdlConfig.hpp"
#include "rtl_model/verilated/PortBits.hpp"

namespace {

using namespace arp;

using vl::HdlConfig;
using vl::get_signed;
using vl::get_unsigned;
using vl::put_field;
using vl::put_vector;
using vl::get_vector;
// An RTL output vector as read, before any narrowing (a wrong wide value must not alias a right one).
struct Vec3Wide {
  int64_t x, y, z;
};

// ---- the valid/ready driver -----------------------------------------------
struct DriveResult {
  size_t compared = 0, mismatches = 0;
  std::string first_mismatch;
  int min_latency = 1 << 30, max_latency = 0;
};

// An optional VCD of the drive: one pixel clock of the default timing (25.175 MHz) per cycle.
struct Wave {
  VerilatedVcdC* vcd = nullptr;
  uint64_t time_ps = 0;
  static constexpr uint64_t kHalfPeriodPs = 19'861;
  void dump() {
    if (vcd) vcd->dump(time_ps);
    time_ps += kHalfPeriodPs;
  }
};

template <class Top>
void tick(Top& top, Wave& wave) {
  top.clk = 1;
  top.eval();
  wave.dump();
  top.clk = 0;
  top.eval();
  wave.dump();
}

// Streams every input through `top`: `apply` puts one on the input ports,
// `check` compares the output ports with input i's expectation and returns a
// description of the difference ("" when equal). in_rate and ready_rate are
// the chances per clock that an input is offered and that the output is taken.
template <class Top>
DriveResult drive(Top& top, size_t n, const std::function<void(Top&, size_t)>& apply,
                  const std::function<std::string(const Top&, size_t)>& check, double in_rate, double ready_rate,
                  uint32_t seed, Wave wave = {}) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  DriveResult r;
  top.clk = 0;
  top.rst_n = 0;
  top.in_valid = 0;
  top.out_ready = 1;
  top.eval();
  tick(top, wave);
  tick(top, wave);
  top.rst_n = 1;
  std::deque<int64_t> accepted_at;  // clock of each accepted input not yet delivered
  size_t next = 0, delivered = 0;
  const int64_t limit = static_cast<int64_t>(n) * 64 + 1000;
  for (int64_t cycle = 0; delivered < n; ++cycle) {
    if (cycle > limit) {
      r.mismatches++;
      if (r.first_mismatch.empty())
        r.first_mismatch = "stream stalled: " + std::to_string(delivered) + " of " + std::to_string(n) + " outputs after " +
                           std::to_string(cycle) + " clocks";
      break;
    }
    const bool offer = next < n && u01(rng) < in_rate;
    top.in_valid = offer;
    if (offer) apply(top, next);
    top.out_ready = u01(rng) < ready_rate;
    top.eval();
    const bool accept = offer && top.in_ready;
    if (top.out_valid && top.out_ready) {
      if (accepted_at.empty()) {
        r.mismatches++;
        if (r.first_mismatch.empty()) r.first_mismatch = "an output at clock " + std::to_string(cycle) + " with no input";
        break;
      }
      const int latency = static_cast<int>(cycle - accepted_at.front());
      accepted_at.pop_front();
      r.min_latency = std::min(r.min_latency, latency);
      r.max_latency = std::max(r.max_latency, latency);
      const std::string d = check(top, delivered);
      r.compared++;
      if (!d.empty()) {
        r.mismatches++;
        if (r.first_mismatch.empty()) r.first_mismatch = "output " + std::to_string(delivered) + ": " + d;
      }
      ++delivered;
    }
    tick(top, wave);
    if (accept) {
      accepted_at.push_back(cycle);
      ++next;
    }
  }
  return r;
}

// Coverage bins: each directed case must be reached at least once.
class Coverage {
 public:
  void declare(const std::string& bin) { bins_[bin]; }
  void hit(const std::string& bin) { bins_[bin]++; }
  void expect_all_hit() const {
    for (const auto& [bin, count] : bins_) EXPECT_GT(count, 0u) << "directed case never reached: " << bin;
  }
  std::string summary() const {
    std::ostringstream s;
    const char* sep = "";
    for (const auto& [bin, count] : bins_) {
      s << sep << bin << " " << count;
      sep = ", ";
    }
    return s.str();
  }

 private:
  std::map<std::string, size_t> bins_;
};

// Both phases: unstalled (every latency exact) then random gaps and back-pressure;
// then the directed cases (every one reached, unless a mutant runs).
template <class Top>
void run_bench(const std::string& unit, size_t n, int latency, bool mutant, const std::function<void(Top&, size_t)>& apply,
               const std::function<std::string(const Top&, size_t)>& check, const Coverage& cov,
               const std::function<void()>& before_teardown) {
  std::printf("%s: %zu vectors\n", unit.c_str(), n);
  size_t mismatches = 0;
  std::string first;
  Top top;  // one instance for both phases: drive() resets it first
  {
    const DriveResult r = drive<Top>(top, n, apply, check, 1.0, 1.0, 1);
    if (!mutant) {
      EXPECT_EQ(r.min_latency, latency) << "unstalled latency in clocks";
      EXPECT_EQ(r.max_latency, latency) << "unstalled latency in clocks";
      EXPECT_EQ(r.compared, n);
    }
    mismatches += r.mismatches;
    first = r.first_mismatch;
    std::printf("unstalled: %zu outputs compared, %zu mismatches, latency %d..%d clocks\n", r.compared, r.mismatches,
                r.min_latency, r.max_latency);
  }
  {
    const DriveResult r = drive<Top>(top, n, apply, check, 0.7, 0.6, 2);
    if (!mutant) {
      EXPECT_GE(r.min_latency, latency) << "latency under back-pressure";
      EXPECT_EQ(r.compared, n);
    }
    mismatches += r.mismatches;
    if (first.empty()) first = r.first_mismatch;
    std::printf("back-pressure (70 %% offered, 60 %% taken): %zu outputs compared, %zu mismatches, latency %d..%d clocks\n",
                r.compared, r.mismatches, r.min_latency, r.max_latency);
  }
  std::printf("directed-case coverage: %s\n", cov.summary().c_str());
  if (!mutant) cov.expect_all_hit();
  if (mutant) {
    EXPECT_GT(mismatches, 0u) << "the mutant passed the bench: the vectors do not reach what it breaks";
    if (!first.empty()) std::printf("mutant caught: %s\n", first.c_str());
  } else {
    EXPECT_EQ(mismatches, 0u) << first;
  }
  if (before_teardown) before_teardown();
}


dp::Vec3q random_unit_vector(std::mt19937& rng, int frac) {
  std::normal_distribution<double> g(0, 1);
  double x = 0, y = 0, z = 0, n = 0;
  while (n < 1e-6) {
    x = g(rng), y = g(rng), z = g(rng);
    n = std::sqrt(x * x + y * y + z * z);
  }
  return {static_cast<int32_t>(dp::quantise_real(x / n, frac, frac + 2)),
          static_cast<int32_t>(dp::quantise_real(y / n, frac, frac + 2)),
          static_cast<int32_t>(dp::quantise_real(z / n, frac, frac + 2))};
}

// ---- orientation matrix unit ---------------------------------------------
template <class Top>
void bench_omu(const HdlConfig& cfg, int mutant, const std::function<void()>& before_teardown = {}) {
  const dp::DatapathWidths w = cfg.widths();
  const dp::RotateParams params(w);
  const int mw = w.mat_frac + 2, vw = w.vec_frac + 2, rw = w.rot_frac + 2;
  const int shift = w.mat_frac + w.vec_frac - w.rot_frac;
  const int64_t mat_one = int64_t{1} << w.mat_frac, vec_one = int64_t{1} << w.vec_frac;
  const dp::SignedRange mat_range(mw), vec_range(vw), rot_range(rw);
  std::vector<dp::Mat3q> ms;
  std::vector<dp::Vec3q> vs;
  auto add = [&](const dp::Mat3q& m, const dp::Vec3q& v) {
    ms.push_back(m);
    vs.push_back(v);
  };
  // Directed: the 24 axis-aligned rotations (signed permutations of det +1)
  // times the axes and (+-1, +-1, +-1).
  std::vector<dp::Vec3q> vecs;
  for (int a = 0; a < 3; ++a)
    for (int s : {1, -1}) {
      dp::Vec3q v{0, 0, 0};
      (a == 0 ? v.x : a == 1 ? v.y : v.z) = static_cast<int32_t>(s * vec_one);
      vecs.push_back(v);
    }
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1})
        vecs.push_back({static_cast<int32_t>(sx * vec_one), static_cast<int32_t>(sy * vec_one),
                        static_cast<int32_t>(sz * vec_one)});
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int p = 0; p < 6; ++p)
    for (int signs = 0; signs < 8; ++signs) {
      const int parity = p < 3 ? 1 : -1;
      const int sgn[3] = {signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? -1 : 1};
      if (parity * sgn[0] * sgn[1] * sgn[2] != 1) continue;  // rotations only
      dp::Mat3q m{};
      for (int r = 0; r < 3; ++r) m.m[3 * r + perms[p][r]] = static_cast<int32_t>(sgn[r] * mat_one);
      for (const dp::Vec3q& v : vecs) add(m, v);
    }
  // Directed: saturation -- the extreme codes in every sign combination.
  for (int64_t mc : {mat_range.hi, mat_range.lo})
    for (int64_t vc : {vec_range.hi, vec_range.lo}) {
      dp::Mat3q m{};
      for (int i = 0; i < 9; ++i) m.m[i] = static_cast<int32_t>(i % 2 ? mat_range.lo + mat_range.hi - mc : mc);
      add(m, {static_cast<int32_t>(vc), static_cast<int32_t>(vc), static_cast<int32_t>(vc)});
      for (int i = 0; i < 9; ++i) m.m[i] = static_cast<int32_t>(mc);
      add(m, {static_cast<int32_t>(vc), static_cast<int32_t>(vc), static_cast<int32_t>(vc)});
    }
  // Directed: exact ties of the rounding (a product sum of (2k + 1) / 2 LSB of the result), both signs.
  if (shift > 0)
    for (int64_t k : {0, 1, 2, 3, 100, -1, -2, -101}) {
      const int64_t target = (2 * k + 1) * (int64_t{1} << (shift - 1));  // = m * v with m = 1 code
      if (!vec_range.contains(target)) continue;
      for (int row = 0; row < 3; ++row) {
        dp::Mat3q m{};
        m.m[3 * row] = 1;
        add(m, {static_cast<int32_t>(target), 0, 0});
      }
    }
  // Random: quantised rotations of quantised unit vectors, then arbitrary codes.
  std::mt19937 rng(20261123);
  std::normal_distribution<double> g(0, 1);
  for (int i = 0; i < 200000; ++i) {
    const dp::Quat q = dp::normalised({g(rng), g(rng), g(rng), g(rng)}, "bench");
    add(dp::quantise_rotation(q, w.mat_frac), random_unit_vector(rng, w.vec_frac));
  }
  std::uniform_int_distribution<int64_t> mat_code(mat_range.lo, mat_range.hi), vec_code(vec_range.lo, vec_range.hi);
  for (int i = 0; i < 50000; ++i) {
    dp::Mat3q m{};
    for (int k = 0; k < 9; ++k) m.m[k] = static_cast<int32_t>(mat_code(rng));
    add(m, {static_cast<int32_t>(vec_code(rng)), static_cast<int32_t>(vec_code(rng)), static_cast<int32_t>(vec_code(rng))});
  }

  // Expectations and coverage from the datapath and the exact sums.
  Coverage cov;
  for (const char* b : {"axis-aligned rotation", "tie", "saturated high", "saturated low"}) cov.declare(b);
  std::vector<dp::Vec3q> expected(ms.size());
  for (size_t i = 0; i < ms.size(); ++i) {
    expected[i] = dp::rotate(ms[i], vs[i], params);
    const int32_t* m = ms[i].m;
    int nonzero = 0;
    for (int k = 0; k < 9; ++k) nonzero += m[k] != 0;
    if (nonzero == 3 && std::abs(m[0]) + std::abs(m[1]) + std::abs(m[2]) == mat_one) cov.hit("axis-aligned rotation");
    for (int r = 0; r < 3; ++r) {
      const int64_t s = int64_t{m[3 * r]} * vs[i].x + int64_t{m[3 * r + 1]} * vs[i].y + int64_t{m[3 * r + 2]} * vs[i].z;
      if (shift > 0 && (s & ((int64_t{1} << shift) - 1)) == (int64_t{1} << (shift - 1))) cov.hit("tie");
      const double exact = std::ldexp(static_cast<double>(s), -shift);
      if (exact > static_cast<double>(rot_range.hi) + 0.5) cov.hit("saturated high");
      if (exact < static_cast<double>(rot_range.lo) - 0.5) cov.hit("saturated low");
    }
  }
  auto apply = [&](Top& top, size_t i) {
    for (int k = 0; k < 9; ++k) put_field(top.in_matrix, k * mw, mw, ms[i].m[k]);
    put_vector(top.in_vector, vw, vs[i]);
  };
  auto check = [&](const Top& top, size_t i) -> std::string {
    const auto [x, y, z] = get_vector<Vec3Wide>(top.out_vector, rw);
    const dp::Vec3q& e = expected[i];
    if (x == e.x && y == e.y && z == e.z) return "";
    std::ostringstream s;
    s << "M = [";
    for (int k = 0; k < 9; ++k) s << (k ? " " : "") << ms[i].m[k];
    s << "], v = (" << vs[i].x << " " << vs[i].y << " " << vs[i].z << "): RTL (" << x << " " << y << " " << z
      << "), datapath (" << e.x << " " << e.y << " " << e.z << ")";
    return s.str();
  };
  run_bench<Top>("orientation matrix unit", ms.size(), cfg.rotate_latency, mutant != 0, apply, check, cov, before_teardown);
}

// ---- cube-face address generator -----------------------------------------
template <class Top>
void bench_cfag(const HdlConfig& cfg, int mutant, const std::function<void()>& before_teardown = {}) {
  const dp::DatapathWidths w = cfg.widths();
  const dp::AddressGeneratorParams params(w, cfg.face_size);
  const int rw = w.rot_frac + 2;
  const int uw = static_cast<int>(std::ceil(std::log2(cfg.face_size + 1))) + w.texel_frac;
  const int64_t one = int64_t{1} << w.rot_frac;
  const int64_t top_code = (int64_t{1} << (w.rot_frac + 1)) - 1;  // the largest |component| of the input contract
  std::vector<dp::Vec3q> rs;
  auto add = [&](int64_t x, int64_t y, int64_t z) {
    rs.push_back({static_cast<int32_t>(x), static_cast<int32_t>(y), static_cast<int32_t>(z)});
  };
  // Directed: the axes, the zero vector, cube edges (two equal magnitudes)
  // and corners (three) in every sign combination, at several magnitudes.
  for (int64_t mag : {one, int64_t{1}, one / 3, top_code, int64_t{12345} % top_code}) {
    add(0, 0, 0);  // after a non-zero vector, so that the input changes
    for (int a = 0; a < 3; ++a)
      for (int s : {1, -1}) add(a == 0 ? s * mag : 0, a == 1 ? s * mag : 0, a == 2 ? s * mag : 0);
    for (int sx : {1, -1})
      for (int sy : {1, -1})
        for (int sz : {1, -1}) {
          add(sx * mag, sy * mag, sz * mag);           // corner
          add(sx * mag, sy * mag, sz * (mag / 2));     // X = Y edge
          add(sx * mag, sy * (mag / 2), sz * mag);     // X = Z edge
          add(sx * (mag / 2), sy * mag, sz * mag);     // Y = Z edge
          add(sx * mag, sy * (mag - 1), sz * (mag / 3));  // just off the edge
        }
  }
  // Directed: every |ma| the input contract allows (every reciprocal table
  // entry and every normaliser shift), with face coordinates at +-1 (the face
  // edges, where positions clamp) and inside the face.
  for (int64_t ma = 1; ma <= top_code; ++ma) {
    add(ma, -ma, ma / 3);
    add(-(ma / 2), ma, -ma);
  }
  // Random: quantised unit directions, then arbitrary codes within the contract.
  std::mt19937 rng(20261124);
  for (int i = 0; i < 200000; ++i) {
    const dp::Vec3q v = random_unit_vector(rng, w.rot_frac);
    add(v.x, v.y, v.z);
  }
  std::uniform_int_distribution<int64_t> code(-top_code, top_code);
  for (int i = 0; i < 50000; ++i) add(code(rng), code(rng), code(rng));

  Coverage cov;
  for (int f = 0; f < 6; ++f) cov.declare(std::string("face ") + dp::face_name(f));
  for (const char* b : {"tie |x| = |y|", "tie |x| = |z|", "tie |y| = |z|", "corner", "zero vector",
                        "clamped to the face's last position", "position 0"})
    cov.declare(b);
  std::vector<dp::CubeAddress> expected(rs.size());
  std::vector<bool> lut_hit(size_t{1} << w.recip_index_bits);
  for (size_t i = 0; i < rs.size(); ++i) {
    expected[i] = dp::generate_address(rs[i], params);
    const int64_t ax = std::abs(int64_t{rs[i].x}), ay = std::abs(int64_t{rs[i].y}), az = std::abs(int64_t{rs[i].z});
    const int64_t ma = std::max({ax, ay, az});
    cov.hit(std::string("face ") + dp::face_name(expected[i].face));
    if (ma > 0 && ax == ay && ax == ma) cov.hit("tie |x| = |y|");
    if (ma > 0 && ax == az && ax == ma) cov.hit("tie |x| = |z|");
    if (ma > 0 && ay == az && ay == ma) cov.hit("tie |y| = |z|");
    if (ma > 0 && ax == ay && ay == az) cov.hit("corner");
    if (ma == 0) cov.hit("zero vector");
    if (expected[i].u == params.max_pos || expected[i].v == params.max_pos) cov.hit("clamped to the face's last position");
    if (expected[i].u == 0 || expected[i].v == 0) cov.hit("position 0");
    if (ma > 0) {
      const int n = 64 - __builtin_clzll(static_cast<uint64_t>(ma));
      const int64_t frac = ma - (int64_t{1} << (n - 1));
      const int below = n - 1 - w.recip_index_bits;
      lut_hit[static_cast<size_t>(below >= 0 ? frac >> below : frac << -below)] = true;
    }
  }
  if (w.divider == dp::DividerKind::ReciprocalLut) {
    cov.declare("every reciprocal table entry");
    if (std::all_of(lut_hit.begin(), lut_hit.end(), [](bool b) { return b; })) cov.hit("every reciprocal table entry");
  }
  auto apply = [&](Top& top, size_t i) {
    put_vector(top.in_vector, rw, rs[i]);
  };
  auto check = [&](const Top& top, size_t i) -> std::string {
    const uint64_t face = top.out_face, u = get_unsigned(top.out_u, 0, uw), v = get_unsigned(top.out_v, 0, uw);
    const dp::CubeAddress& e = expected[i];
    if (face == e.face && static_cast<int64_t>(u) == e.u && static_cast<int64_t>(v) == e.v) return "";
    std::ostringstream s;
    s << "r = (" << rs[i].x << " " << rs[i].y << " " << rs[i].z << "): RTL face " << dp::face_name(static_cast<int>(face))
      << " u " << u << " v " << v << ", datapath face " << dp::face_name(e.face) << " u " << e.u << " v " << e.v;
    return s.str();
  };
  run_bench<Top>("cube-face address generator", rs.size(), cfg.address_latency, mutant != 0, apply, check, cov, before_teardown);
}

// ---- composition unit ------------------------------------------------------
template <class Top>
void bench_comp(const HdlConfig& cfg, int mutant, const std::function<void()>& before_teardown = {}) {
  const dp::MemoryFormat f = cfg.format();
  dp::CompositionParams params(f, {0, 0, 0});
  params.background = static_cast<uint32_t>(cfg.background);
  const int n = cfg.memories, cb = f.color_bits_total();
  const uint32_t empty = f.empty_depth(), max_color = static_cast<uint32_t>((uint64_t{1} << cb) - 1);
  std::mt19937 rng(20261125);
  std::uniform_int_distribution<uint32_t> color(0, max_color), depth(0, empty), small(0, 3), pick(0, 7);
  std::vector<std::vector<uint64_t>> words;
  // A stored depth has the code's width (empty is all its ones): the bench's fixed codes are masked to it.
  auto word = [empty](uint32_t c, uint32_t d) { return (uint64_t{d & empty} << 32) | c; };
  // Directed: all empty; one memory holding the texel, in each position; all at
  // one depth (ties); depth 0 and the deepest non-empty code.
  words.push_back(std::vector<uint64_t>(static_cast<size_t>(n), word(color(rng), empty)));
  for (int k = 0; k < n; ++k) {
    std::vector<uint64_t> w(static_cast<size_t>(n), word(color(rng), empty));
    w[static_cast<size_t>(k)] = word(color(rng), std::min<uint32_t>(5, empty - 1));  // (written at any width)
    words.push_back(w);
    for (uint32_t d : {0u, empty - 1, std::min(7u, empty - 1)}) {
      std::vector<uint64_t> t(static_cast<size_t>(n));
      for (auto& x : t) x = word(color(rng), d);
      words.push_back(t);
    }
  }
  // Random: depths from a few values (many ties) or anywhere, empty one time in four.
  for (int i = 0; i < 100000; ++i) {
    std::vector<uint64_t> w(static_cast<size_t>(n));
    for (auto& x : w) {
      const uint32_t p = pick(rng);
      x = word(color(rng), p < 2 ? empty : p < 5 ? small(rng) : depth(rng));
    }
    words.push_back(w);
  }
  Coverage cov;
  for (const char* b : {"every memory empty", "tie between memories", "depth 0"}) cov.declare(b);
  for (int k = 0; k < n; ++k) cov.declare("memory " + std::to_string(k) + " wins");
  std::vector<dp::Composite> expected(words.size());
  for (size_t i = 0; i < words.size(); ++i) {
    expected[i] = dp::compose(words[i].data(), n, params);
    if (expected[i].memory < 0) cov.hit("every memory empty");
    else cov.hit("memory " + std::to_string(expected[i].memory) + " wins");
    if (expected[i].depth == 0) cov.hit("depth 0");
    int at_best = 0;
    for (uint64_t x : words[i]) at_best += dp::texel_depth(x) == expected[i].depth;
    if (expected[i].memory >= 0 && at_best > 1) cov.hit("tie between memories");
  }
  const int iw = n > 1 ? static_cast<int>(std::ceil(std::log2(n))) : 1;
  auto apply = [&](Top& top, size_t i) {
    for (int k = 0; k < n; ++k) put_field(top.in_texels, 64 * k, 64, static_cast<int64_t>(words[i][static_cast<size_t>(k)]));
  };
  auto check = [&](const Top& top, size_t i) -> std::string {
    const uint64_t c = get_unsigned(top.out_color, 0, cb), d = get_unsigned(top.out_depth, 0, f.depth_bits);
    const bool is_empty = top.out_empty;
    const int64_t who = is_empty ? -1 : static_cast<int64_t>(get_unsigned(top.out_memory, 0, iw));
    const dp::Composite& e = expected[i];
    if (c == e.color && d == e.depth && who == e.memory) return "";
    std::ostringstream s;
    s << "depths (";
    for (uint64_t x : words[i]) s << " " << dp::texel_depth(x);
    s << " ): RTL colour " << c << " depth " << d << " memory " << who << ", datapath colour " << e.color << " depth "
      << e.depth << " memory " << e.memory;
    return s.str();
  };
  run_bench<Top>("composition unit (" + std::to_string(n) + " memories)", words.size(), cfg.compose_latency, mutant != 0, apply, check, cov, before_teardown);
}

// ---- bilinear filter ---------------------------------------------------------
template <class Top>
void bench_filt(const HdlConfig& cfg, int mutant, const std::function<void()>& before_teardown = {}) {
  const dp::MemoryFormat f = cfg.format();
  const dp::ChannelLayout layout(f);
  const int tf = cfg.texel_frac, cb = f.color_bits_total();
  const uint32_t wmax = (1u << tf) - 1, max_color = static_cast<uint32_t>((uint64_t{1} << cb) - 1);
  struct In {
    uint32_t c[4], wx, wy;
  };
  std::vector<In> ins;
  std::mt19937 rng(20261126);
  std::uniform_int_distribution<uint32_t> color(0, max_color), weight(0, wmax);
  // Directed: weights at 0, 1, half and the largest, with the extreme colours and random ones.
  for (uint32_t wx : {0u, 1u, wmax / 2 + 1, wmax})
    for (uint32_t wy : {0u, 1u, wmax / 2 + 1, wmax}) {
      ins.push_back({{max_color, max_color, max_color, max_color}, wx, wy});
      ins.push_back({{0, max_color, 0, max_color}, wx, wy});
      ins.push_back({{color(rng), color(rng), color(rng), color(rng)}, wx, wy});
    }
  for (int i = 0; i < 200000; ++i) ins.push_back({{color(rng), color(rng), color(rng), color(rng)}, weight(rng), weight(rng)});
  Coverage cov;
  for (const char* b : {"weights 0", "largest weights", "all channels at full scale", "exact half before rounding"})
    cov.declare(b);
  std::vector<uint32_t> expected(ins.size());
  const uint64_t W = uint64_t{1} << tf, half = uint64_t{1} << (2 * tf - 1), mask = (uint64_t{1} << (2 * tf)) - 1;
  for (size_t i = 0; i < ins.size(); ++i) {
    const In& x = ins[i];
    expected[i] = dp::bilinear_blend(x.c[0], x.c[1], x.c[2], x.c[3], x.wx, x.wy, tf, layout);
    if (x.wx == 0 && x.wy == 0) cov.hit("weights 0");
    if (x.wx == wmax && x.wy == wmax) cov.hit("largest weights");
    if (x.c[0] == max_color && x.c[1] == max_color && x.c[2] == max_color && x.c[3] == max_color)
      cov.hit("all channels at full scale");
    for (int c = 0; c < 3; ++c) {  // the exact blend of a channel, independently of the datapath's rounding
      auto ch = [&](uint32_t v) { return uint64_t{(v >> layout.shift[c]) & layout.mask[c]}; };
      const uint64_t sum = (ch(x.c[0]) * (W - x.wx) + ch(x.c[1]) * x.wx) * (W - x.wy) +
                           (ch(x.c[2]) * (W - x.wx) + ch(x.c[3]) * x.wx) * x.wy;
      if ((sum & mask) == half) cov.hit("exact half before rounding");
    }
  }
  auto apply = [&](Top& top, size_t i) {
    for (int k = 0; k < 4; ++k) put_field(top.in_taps, k * cb, cb, ins[i].c[k]);
    top.in_wx = ins[i].wx;
    top.in_wy = ins[i].wy;
  };
  auto check = [&](const Top& top, size_t i) -> std::string {
    const uint64_t c = get_unsigned(top.out_color, 0, cb);
    if (c == expected[i]) return "";
    std::ostringstream s;
    s << "taps " << ins[i].c[0] << " " << ins[i].c[1] << " " << ins[i].c[2] << " " << ins[i].c[3] << ", weights "
      << ins[i].wx << " " << ins[i].wy << ": RTL " << c << ", datapath " << expected[i];
    return s.str();
  };
  run_bench<Top>("bilinear filter", ins.size(), cfg.filter_latency, mutant != 0, apply, check, cov, before_teardown);
}

// The coverage bench: the module's bench on a build with Verilator's
// coverage, the counters written to hdl_<module>_coverage.dat (for
// `verilator_coverage --annotate`), and the share of line, branch and toggle
// points reached per kind. Every line and branch point must be reached.
struct CoverageKind {
  size_t points = 0, reached = 0;
};
std::map<std::string, CoverageKind> read_coverage(const std::string& path, std::vector<std::string>& missed) {
  std::map<std::string, CoverageKind> kinds;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("C '", 0) != 0) continue;
    const size_t close = line.rfind('\'');
    const std::string key = line.substr(3, close - 3);
    const unsigned long long count = std::stoull(line.substr(close + 1));
    auto field = [&](const std::string& name) {
      const std::string tag = std::string("\x01") + name + "\x02";
      const size_t at = key.find(tag);
      if (at == std::string::npos) return std::string();
      const size_t from = at + tag.size(), to = key.find('\x01', from);
      return key.substr(from, to == std::string::npos ? std::string::npos : to - from);
    };
    std::string kind = field("page");
    kind = kind.substr(0, kind.find('/'));
    CoverageKind& k = kinds[kind];
    k.points++;
    if (count > 0) k.reached++;
    else if (kind != "v_toggle") missed.push_back(kind + " " + field("f") + ":" + field("l") + " " + field("o"));
  }
  return kinds;
}

// The waveform bench: a short stream through the traced model with gaps and
// back-pressure, written as a VCD, and the committed GTKWave save file
// (waveforms/hdl_<module>.gtkw) checked against the signals the VCD declares.
template <class Top>
void trace_omu(const HdlConfig& cfg, const std::string& module) {
  const dp::DatapathWidths w = cfg.widths();
  const dp::RotateParams params(w);
  const int mw = w.mat_frac + 2, vw = w.vec_frac + 2, rw = w.rot_frac + 2;
  const std::string vcd_path = "hdl_" + module + ".vcd";
  std::vector<dp::Mat3q> ms;
  std::vector<dp::Vec3q> vs;
  std::mt19937 rng(7);
  for (int i = 0; i < 32; ++i) {
    ms.push_back(dp::quantise_rotation(dp::from_yaw_pitch_roll_deg(11.25 * i, 5.0 * (i % 5), 0), w.mat_frac));
    vs.push_back(random_unit_vector(rng, w.vec_frac));
  }
  Verilated::traceEverOn(true);
  Top top;
  VerilatedVcdC vcd;
  top.trace(&vcd, 99);
  vcd.open(vcd_path.c_str());
  Wave wave{&vcd, 0};
  const DriveResult r = drive<Top>(
      top, ms.size(),
      [&](Top& t, size_t i) {
        for (int k = 0; k < 9; ++k) put_field(t.in_matrix, k * mw, mw, ms[i].m[k]);
        put_vector(t.in_vector, vw, vs[i]);
      },
      [&](const Top& t, size_t i) -> std::string {
        const dp::Vec3q e = dp::rotate(ms[i], vs[i], params);
        const Vec3Wide got = get_vector<Vec3Wide>(t.out_vector, rw);
        const bool same = got.x == e.x && got.y == e.y && got.z == e.z;
        return same ? "" : "differs from the datapath";
      },
      0.8, 0.7, 3, wave);
  vcd.close();
  EXPECT_EQ(r.mismatches, 0u) << r.first_mismatch;
  EXPECT_EQ(r.compared, ms.size());

  // Every signal of the save file is declared in the VCD (scope.name, as GTKWave shows it).
  std::ifstream in(vcd_path);
  ASSERT_TRUE(in) << vcd_path;
  std::set<std::string> declared;
  std::vector<std::string> scope;
  std::string tok;
  while (in >> tok) {
    if (tok == "$scope") {
      std::string kind, name;
      in >> kind >> name;
      scope.push_back(name);
    } else if (tok == "$upscope") {
      if (!scope.empty()) scope.pop_back();
    } else if (tok == "$var") {
      std::string kind, width, id, name, range;
      in >> kind >> width >> id >> name >> range;
      std::string full;
      for (const std::string& sc : scope) full += sc + ".";
      declared.insert(full + name + (range.rfind('[', 0) == 0 ? range : ""));
    } else if (tok == "$enddefinitions") {
      break;
    }
  }
  const std::string gtkw = std::string(ARPSIM_SOURCE_DIR) + "/waveforms/hdl_" + module + ".gtkw";
  std::ifstream save(gtkw);
  ASSERT_TRUE(save) << gtkw;
  std::string line;
  int signals = 0;
  while (std::getline(save, line)) {
    if (line.empty() || line[0] == '[' || line[0] == '@' || line[0] == '*' || line[0] == '-') continue;
    ++signals;
    EXPECT_TRUE(declared.count(line)) << gtkw << ": signal '" << line << "' is not in the VCD";
  }
  EXPECT_GE(signals, 8) << gtkw << " names too few signals";
  std::printf("wrote %s: %zu signals declared, %d shown by %s\n", vcd_path.c_str(), declared.size(), signals, gtkw.c_str());
}

}  // namespace

// One test per verilated model: HdlBench.<module>_<configuration>_m<mutant>.
#define ARP_HDL_TEST(module, config, mutant, cls, ...)                                   \
  TEST(HdlBench, module##_##config##_m##mutant) {                                        \
    HdlConfig c{};                                                                       \
    (__VA_ARGS__);                                                                       \
    bench_##module<cls>(c, mutant);                                                      \
  }
ARP_HDL_MODELS(ARP_HDL_TEST)

// The traced model: HdlWaveform.<module>.
#define ARP_HDL_WAVE_TEST(module, config, mutant, cls, ...) \
  TEST(HdlWaveform, module) {                                \
    HdlConfig c{};                                           \
    (__VA_ARGS__);                                           \
    trace_##module<cls>(c, #module);                         \
  }
ARP_HDL_TRACED_MODEL(ARP_HDL_WAVE_TEST)

// The coverage builds: HdlCoverage.<module>.
#define ARP_HDL_COVERAGE_TEST(module, config, mutant, cls, ...)                                 \
  TEST(HdlCoverage, module) {                                                                  \
    HdlConfig c{};                                                                             \
    (__VA_ARGS__);                                                                             \
    const std::string path = "hdl_" #module "_coverage.dat";                                  \
    bench_##module<cls>(c, 0, [&] { /* while the model (its counters) lives */                 \
      Verilated::threadContextp()->coveragep()->write(path.c_str());                          \
      Verilated::threadContextp()->coveragep()->clear();                                       \
    });                                                                                        \
    std::vector<std::string> missed;                                                           \
    const auto kinds = read_coverage(path, missed);                                            \
    for (const auto& [kind, k] : kinds)                                                        \
      std::printf("%s: %zu of %zu points reached\n", kind.c_str(), k.reached, k.points);      \
    EXPECT_GT(kinds.count("v_line"), 0u) << path << " has no line coverage";                   \
    for (const std::string& m : missed) ADD_FAILURE() << "never reached: " << m;               \
  }
ARP_HDL_COVERAGE_MODELS(ARP_HDL_COVERAGE_TEST)

// One fact in two places kept equal: the first line of configurations.txt
// (the default build) is the datapath's default configuration, latencies
// included (timed.*_latency).
TEST(HdlConfiguration, TheDefaultBuildIsTheDefaultConfiguration) {
  const HdlConfig want = vl::hdl_config_of(dp::ArpConfig{});
  int compared = 0;
#define ARP_HDL_FIELD_EQ(field) EXPECT_EQ(c.field, want.field) << where << #field;
#define ARP_HDL_CHECK_DEFAULT(module, config, mutant, cls, ...) \
  if (std::string(#config) == "default") {                      \
    HdlConfig c{};                                              \
    (__VA_ARGS__);                                              \
    const std::string where = #module " build 'default': ";     \
    ARP_HDL_PARAMS_##module(ARP_HDL_FIELD_EQ);                  \
    ++compared;                                                 \
  }
  ARP_HDL_PRODUCT_MODELS(ARP_HDL_CHECK_DEFAULT)
#undef ARP_HDL_CHECK_DEFAULT
#undef ARP_HDL_FIELD_EQ
  EXPECT_EQ(compared, 4) << "one default build per module";
  // the latencies, which no module's parameter list holds
  HdlConfig c{};
#define ARP_HDL_TRACED_DEFAULT(module, config, mutant, cls, ...) (__VA_ARGS__);
  ARP_HDL_TRACED_MODEL(ARP_HDL_TRACED_DEFAULT)
#undef ARP_HDL_TRACED_DEFAULT
  EXPECT_EQ(c.rotate_latency, want.rotate_latency);
  EXPECT_EQ(c.address_latency, want.address_latency);
  EXPECT_EQ(c.compose_latency, want.compose_latency);
  EXPECT_EQ(c.filter_latency, want.filter_latency);
}
