// Per-module benches: each stage's SC_MODULE alone between a stimulus
// driver and a response monitor (StageBench.hpp), with directed and
// seeded-random stimulus. Scoreboards check every output bit-exact against
// the datapath functions called directly, the latency exactly (unstalled
// half) or at least (stalled half), the order, and bounds against the golden
// reference. One TEST = one simulation = one process under ctest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "BenchSupport.hpp"
#include "StageBench.hpp"
#include "rtl_model/systemc/AntiAliasingFilter.hpp"
#include "rtl_model/systemc/CompositionUnit.hpp"
#include "rtl_model/systemc/CubeFaceAddressGenerator.hpp"
#include "rtl_model/systemc/DisplayMemoryBanks.hpp"
#include "rtl_model/systemc/HmdScanOut.hpp"
#include "rtl_model/systemc/LensVectorTable.hpp"
#include "rtl_model/systemc/OrientationMatrixUnit.hpp"
#include "rtl_model/systemc/VideoTimingGenerator.hpp"
#include "reference/golden/GoldenReference.hpp"

using namespace arp;
using namespace arp::bench;
using namespace sc_core;

namespace {

// Everything a stage module needs around it: the run's inputs, from which
// each bench elaborates the one module under test.
struct World {
  dp::ArpConfig c = small_config();
  std::unique_ptr<dp::DisplayMemorySet> mem;
  dp::OrientationStream stream = dp::OrientationStream::constant(dp::Quat{});
  stage::TimedInputs in;
  void build() {
    mem = std::make_unique<dp::DisplayMemorySet>(c.memory, c.timing.eyes);
    fill_memories(*mem);
    in.config = c;
    in.memories = mem.get();
    in.orientation = &stream;
    in.frames = 3;
  }
  stage::StageContext context() const { return {in, dp::PipelineSchedule(c)}; }
  // The pixel clock to `end` and a FIFO of the configured depth.
  scm::ClockGenerator clock(int64_t end) const { return scm::ClockGenerator("clock", c.timing.pixel_clock_hz, 0, 0, end); }
  template <class T>
  scm::FifoChannel<T> fifo(const char* name) const {
    return scm::FifoChannel<T>(name, c.timed.fifo_depth);
  }
};

template <class In, class Out>
struct Result {
  std::vector<In> stimulus;
  std::vector<Out> got;
  std::vector<int64_t> write_cycle, read_cycle;
  size_t phase_one = 0;
  int64_t forwarded_calls = 0;  // calls the module made through ForwardingFifos
  int64_t forwarded_clock_calls = 0;  // cycle reads through a ForwardingClock
  bool clock_direct = false;          // the module read its ClockGenerator's cycle without the interface
  std::vector<std::string> processes;  // the module's own processes (none when its ClockGenerator runs it)
};

// A channel with the FIFO's two interfaces that is not a FifoChannel: it
// forwards every call to one and counts them. A stage module bound to it
// calls it through the interfaces' virtual functions (StageModule), not
// directly as it calls a FifoChannel: a bench through these shows both paths
// behave alike.
template <class T>
class ForwardingFifo : public sc_core::sc_channel, public scm::FifoWriteIf<T>, public scm::FifoReadIf<T> {
 public:
  ForwardingFifo(sc_core::sc_module_name n, scm::FifoChannel<T>& f) : sc_core::sc_channel(n), f_(f) {}
  bool can_write() const override { return counted().can_write(); }
  void write(const T& v, int64_t cycle) override { counted().write(v, cycle); }
  T& emplace(int64_t cycle) override { return counted().emplace(cycle); }
  void note_blocked() override { counted().note_blocked(); }
  bool can_read() const override { return counted().can_read(); }
  const T& front() const override { return counted().front(); }
  void read(int64_t cycle) override { counted().read(cycle); }
  mutable int64_t calls = 0;

 private:
  scm::FifoChannel<T>& counted() const {
    ++calls;
    return f_;
  }
  scm::FifoChannel<T>& f_;
};

// A clock channel that is not a ClockGenerator: the generator's edges and
// cycle through the interface, counting the cycle reads.
class ForwardingClock : public sc_core::sc_prim_channel, public scm::ClockIf {
 public:
  ForwardingClock(const char* name, scm::ClockGenerator& gen) : sc_prim_channel(name), gen_(gen) {}
  int64_t cycle() const override {
    ++calls;
    return gen_.cycle();
  }
  const sc_core::sc_event& posedge_event() const override { return gen_.posedge_event(); }
  mutable int64_t calls = 0;

 private:
  scm::ClockGenerator& gen_;
};

// With ARPSIM_BENCH_VCD=DIR, a bench writes DIR/bench_<test>.vcd: the clock,
// both FIFOs' occupancy and everything the module under test traces
// (waveforms/bench_<test>.gtkw is its view).
class BenchWaveform {
 public:
  BenchWaveform(scm::ClockGenerator& gen, const int& in_occupancy, const int& out_occupancy) {
    const char* dir = std::getenv("ARPSIM_BENCH_VCD");
    if (!dir) return;
    const std::string name = std::string(dir) + "/bench_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    tf_ = sc_create_vcd_trace_file(name.c_str());
    tf_->set_time_unit(1, SC_PS);
    gen.trace(tf_, "bench.clk");
    gen.trace_cycle(tf_, "bench.cycle");
    sc_trace(tf_, in_occupancy, "stimulus_fifo.occupancy");
    sc_trace(tf_, out_occupancy, "response_fifo.occupancy");
  }
  ~BenchWaveform() {
    if (tf_) sc_close_vcd_trace_file(tf_);
  }
  BenchWaveform(const BenchWaveform&) = delete;
  BenchWaveform& operator=(const BenchWaveform&) = delete;
  sc_trace_file* file() const { return tf_; }

 private:
  sc_trace_file* tf_ = nullptr;
};

// Runs a stage module, elaborated alone, between a driver and a monitor for `cycles` pixel clocks.
template <class Module>
Result<typename Module::Input, typename Module::Output> run_bench(World& w, std::vector<typename Module::Input> stimulus,
                                                                  int64_t cycles, std::unique_ptr<Module>* keep = nullptr,
                                                                  int64_t phase_two_cycle = 0, bool through_interfaces = false) {
  using In = typename Module::Input;
  using Out = typename Module::Output;
  sc_set_time_resolution(1, SC_PS);
  sc_report_handler::set_actions(SC_INFO, SC_DO_NOTHING);
  scm::ClockGenerator gen = w.clock(cycles);
  const int64_t host_cycles = dp::clock_cycle_at_or_after(dp::clock_cycle_to_ps(cycles, w.c.timing.pixel_clock_hz),
                                                          w.c.timed.host_clock_hz);
  scm::ClockGenerator host_gen("host_clock", w.c.timed.host_clock_hz, 0, 0, host_cycles);
  scm::FifoChannel<In> in_fifo = w.fifo<In>("stimulus_fifo");
  scm::FifoChannel<Out> out_fifo = w.fifo<Out>("response_fifo");
  StimulusDriver<In> drv("driver", stimulus, 11);
  drv.phase_two_cycle = phase_two_cycle;
  drv.clk(gen);
  drv.stimulus_out(in_fifo);
  auto dut = std::make_unique<Module>("dut", w.context());
  ForwardingClock clock_forward("clock_forward", gen);
  if (through_interfaces) dut->clk(clock_forward);
  else dut->clk(gen);
  if constexpr (std::is_same_v<Module, scm::DisplayMemoryBanks>) {
    dut->host_clk(host_gen);
    const Module& d = *dut;
    host_gen.gate([&d](int64_t n) { return d.host_port().next_active_cycle(n); });
  }
  ForwardingFifo<In> in_forward("stimulus_forward", in_fifo);
  ForwardingFifo<Out> out_forward("response_forward", out_fifo);
  if (through_interfaces) {
    dut->input(in_forward);
    dut->output(out_forward);
  } else {
    dut->input(in_fifo);
    dut->output(out_fifo);
  }
  ResponseMonitor<Out> mon("monitor", drv.phase_one(), 23);
  mon.clk(gen);
  mon.response_in(out_fifo);
  BenchWaveform wave(gen, in_fifo.core().occupancy_ref(), out_fifo.core().occupancy_ref());
  if (wave.file()) dut->trace(wave.file());
  sc_start(sc_time::from_value(static_cast<sc_time::value_type>(dp::clock_cycle_to_ps(cycles + 1, w.c.timing.pixel_clock_hz))));
  Result<In, Out> r;
  r.stimulus = std::move(stimulus);
  r.got = mon.got;
  r.write_cycle = drv.write_cycle;
  r.read_cycle = mon.read_cycle;
  r.phase_one = drv.phase_one();
  r.forwarded_calls = in_forward.calls + out_forward.calls;
  r.forwarded_clock_calls = clock_forward.calls;
  r.clock_direct = dut->reads_clock_directly();
  for (const sc_core::sc_object* o : dut->get_child_objects())
    if (dynamic_cast<const sc_core::sc_process_b*>(o)) r.processes.push_back(o->name());
  if (keep) *keep = std::move(dut);
  return r;
}

int64_t slot_cycle_of(const stage::PixelSlot& s) { return s.slot_cycle; }
template <class T>
int64_t slot_cycle_of(const T& t) {
  return t.slot.slot_cycle;
}

// Every item came out, in order; unstalled items took exactly the latency (+1: the driver's FIFO).
template <class In, class Out>
void check_flow(const Result<In, Out>& r, int latency) {
  ASSERT_EQ(r.got.size(), r.stimulus.size()) << "pixels lost or stuck";
  for (size_t i = 0; i < r.got.size(); ++i) {
    ASSERT_EQ(slot_cycle_of(r.got[i]), slot_cycle_of(r.stimulus[i])) << "out of order at " << i;
    const int64_t took = r.read_cycle[i] - r.write_cycle[i];
    if (i + 2 < r.phase_one) {
      EXPECT_EQ(took, latency + 1) << "item " << i;
    } else {
      EXPECT_GE(took, latency + 1) << "item " << i;
    }
  }
}

stage::PixelSlot slot_of(int64_t i, int x, int y) {
  stage::PixelSlot s;
  s.frame = 0;
  s.slot_cycle = 1000 + i;  // distinct, increasing: the order check
  s.x = x;
  s.y = y;
  s.eye_first = 0;
  s.eye_count = 2;
  return s;
}

int lat(const World& w, dp::Stage s) { return w.c.timed.stage[static_cast<size_t>(s)].latency_cycles; }

dp::Vec3q random_vector(std::mt19937& rng, int frac) {
  std::normal_distribution<double> n;
  double x = n(rng), y = n(rng), z = n(rng);
  const double l = std::sqrt(x * x + y * y + z * z);
  const double one = std::ldexp(1.0, frac);
  return {static_cast<int32_t>(std::lround(x / l * one)), static_cast<int32_t>(std::lround(y / l * one)),
          static_cast<int32_t>(std::lround(z / l * one))};
}

}  // namespace

TEST(ModuleBench, LensVectorTable) {
  World w;
  w.build();
  std::mt19937 rng(1);
  std::vector<stage::PixelSlot> stim;
  const int W = w.c.timing.h_active, H = w.c.timing.v_active;
  for (auto [x, y] : {std::pair{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}, {W / 2, H / 2}})
    stim.push_back(slot_of(static_cast<int64_t>(stim.size()), x, y));
  while (stim.size() < 400)
    stim.push_back(slot_of(static_cast<int64_t>(stim.size()), std::uniform_int_distribution<int>(0, W - 1)(rng),
                           std::uniform_int_distribution<int>(0, H - 1)(rng)));
  auto r = run_bench<scm::LensVectorTable>(w, stim, 2000);
  check_flow(r, lat(w, dp::Stage::Lens));
  const dp::LensVectorTable table(w.c.lens, w.c.timing, w.c.widths.vec_frac);
  const double lsb = std::ldexp(1.0, -w.c.widths.vec_frac);
  for (size_t i = 0; i < r.got.size(); ++i)
    for (int e = 0; e < 2; ++e) {
      const auto& s = r.stimulus[i];
      const dp::Vec3q want = table.at(e, s.x, s.y);
      const dp::Vec3q& v = r.got[i].view[e];
      ASSERT_TRUE(v.x == want.x && v.y == want.y && v.z == want.z) << "item " << i;
      const glm::dvec3 g = golden::lens_direction(w.c, e, s.x, s.y);
      EXPECT_NEAR(v.x * lsb, g.x, lsb);
      EXPECT_NEAR(v.y * lsb, g.y, lsb);
      EXPECT_NEAR(v.z * lsb, g.z, lsb);
    }
}

TEST(ModuleBench, OrientationMatrixUnit) {
  World w;
  w.c.pipeline.latch_lead_cycles = 3;
  // A new random orientation every 37 clocks; latch points at random pixels.
  std::mt19937 rng(2);
  std::vector<dp::OrientationSample> samples;
  std::normal_distribution<double> n;
  for (int i = 0; i < 80; ++i)
    samples.push_back({dp::clock_cycle_to_ps(37 * i, w.c.timing.pixel_clock_hz), dp::Quat{n(rng), n(rng), n(rng), n(rng)}});
  w.stream = dp::OrientationStream(samples, "random orientations");
  w.build();
  std::vector<stage::LensToken> stim;
  const int F = w.c.widths.vec_frac;
  const int32_t one = 1 << F;
  const dp::Vec3q axes[] = {{one, 0, 0}, {-one, 0, 0}, {0, one, 0}, {0, -one, 0}, {0, 0, one}, {0, 0, -one}};
  for (int i = 0; i < 600; ++i) {
    stage::LensToken t;
    t.slot = slot_of(i, 0, 0);
    t.slot.latch = i == 0 || std::bernoulli_distribution(0.2)(rng);
    t.view[0] = i < 6 ? axes[i] : random_vector(rng, F);
    t.view[1] = random_vector(rng, F);
    stim.push_back(t);
  }
  auto r = run_bench<scm::OrientationMatrixUnit>(w, stim, 2800);
  check_flow(r, lat(w, dp::Stage::Rotate));
  const dp::RotateParams rp(w.c.widths);
  const dp::VideoTiming t(w.c.timing);
  const double lsb = std::ldexp(1.0, -w.c.widths.rot_frac);
  uint32_t held = 0;
  for (size_t i = 0; i < r.got.size(); ++i) {
    const auto& g = r.got[i];
    if (r.stimulus[i].slot.latch && i + 2 < r.phase_one) {
      // Unstalled: it entered the unit the clock after it was written; the register is read latch_lead earlier.
      const int64_t entry = r.write_cycle[i] + 1;
      EXPECT_EQ(g.sample, w.stream.index_at(t.cycles_to_ps(entry - w.c.pipeline.latch_lead_cycles))) << "item " << i;
    }
    if (!r.stimulus[i].slot.latch) {
      EXPECT_EQ(g.sample, held) << "item " << i << " changed sample without a latch";
    }
    held = g.sample;
    const dp::Mat3q M = dp::quantise_rotation(w.stream[g.sample].q, w.c.widths.mat_frac);
    const glm::dmat3 R = golden::rotation(glm::dquat(w.stream[g.sample].q.w, w.stream[g.sample].q.x,
                                                     w.stream[g.sample].q.y, w.stream[g.sample].q.z));
    for (int e = 0; e < 2; ++e) {
      const dp::Vec3q want = dp::rotate(M, r.stimulus[i].view[e], rp);
      ASSERT_TRUE(g.world[e].x == want.x && g.world[e].y == want.y && g.world[e].z == want.z) << "item " << i;
      const dp::Vec3q& v = r.stimulus[i].view[e];
      const double vl = std::ldexp(1.0, -w.c.widths.vec_frac);
      const glm::dvec3 exact = R * glm::dvec3(v.x * vl, v.y * vl, v.z * vl);
      EXPECT_NEAR(g.world[e].x * lsb, exact.x, 3 * lsb);
      EXPECT_NEAR(g.world[e].y * lsb, exact.y, 3 * lsb);
      EXPECT_NEAR(g.world[e].z * lsb, exact.z, 3 * lsb);
    }
  }
}

TEST(ModuleBench, CubeFaceAddressGenerator) {
  World w;
  w.build();
  std::mt19937 rng(3);
  const int F = w.c.widths.rot_frac;
  const int32_t one = 1 << F, h = one / 2;
  // Directed: axes, cube edges and corners (exact ties), near-ties, the extremes of the range.
  std::vector<dp::Vec3q> dirs = {{one, 0, 0},   {-one, 0, 0},  {0, one, 0},    {0, -one, 0},   {0, 0, one},
                                 {0, 0, -one},  {h, h, 0},     {-h, h, 0},     {h, -h, -h},    {-h, -h, -h},
                                 {h, h, h},     {h, h - 1, h}, {h - 1, h, h},  {0, h, h},      {0, -h, h},
                                 {2 * one - 1, 0, 0}, {-2 * one + 1, 2 * one - 1, 2 * one - 1}, {1, 0, 0}, {0, 0, 1}};
  std::vector<stage::RotatedToken> stim;
  for (int i = 0; i < 700; ++i) {
    stage::RotatedToken t;
    t.slot = slot_of(i, 0, 0);
    t.sample = 0;
    t.world[0] = i < static_cast<int>(dirs.size()) ? dirs[static_cast<size_t>(i)] : random_vector(rng, F);
    t.world[1] = random_vector(rng, F);
    stim.push_back(t);
  }
  auto r = run_bench<scm::CubeFaceAddressGenerator>(w, stim, 3000);
  check_flow(r, lat(w, dp::Stage::Address));
  const dp::AddressGeneratorParams ap(w.c.widths, w.c.memory.face_size);
  const double tf = std::ldexp(1.0, -w.c.widths.texel_frac);
  int same_face = 0, compared = 0;
  for (size_t i = 0; i < r.got.size(); ++i)
    for (int e = 0; e < 2; ++e) {
      const dp::Vec3q& v = r.stimulus[i].world[e];
      const dp::CubeAddress want = dp::generate_address(v, ap);  // the datapath, computing the reciprocal
      const dp::CubeAddress& a = r.got[i].address[e];
      ASSERT_TRUE(a.face == want.face && a.x == want.x && a.y == want.y && a.fx == want.fx && a.fy == want.fy &&
                  a.u == want.u && a.v == want.v)
          << "item " << i << " eye " << e;
      const golden::Address g = golden::address(glm::dvec3(v.x, v.y, v.z), w.c.memory.face_size);
      ++compared;
      if (g.face == a.face) {
        ++same_face;
        EXPECT_NEAR(a.u * tf, g.u, 0.1) << "item " << i;
        EXPECT_NEAR(a.v * tf, g.v, 0.1) << "item " << i;
      }
    }
  EXPECT_EQ(same_face, compared) << "the same vector must select the same face, ties included";
}

TEST(ModuleBench, DisplayMemoryBanks) {
  World w;
  w.c.memory.count = 3;
  w.c.timed.host_clock_hz = 5'000'000;
  w.build();
  // A host job rewrites memory 1 of eye 1 during the run; it swaps at the first vertical blank.
  const dp::VideoTiming t(w.c.timing);
  stage::HostWriteJob job;
  job.start_ps = 0;
  job.eye = 1;
  job.memory = 1;
  for (int y = 0; y < 64; y += 2)
    for (int x = 0; x < 64; x += 3) job.texels.push_back({5, static_cast<uint16_t>(x), static_cast<uint16_t>(y), 0x00ff00u, 5});
  w.in.host_jobs = {job};
  const int64_t swap = dp::PipelineSchedule(w.c).swap_cycle(0);
  // Reference memories: before and after the swap.
  dp::DisplayMemorySet before(w.c.memory, 2), after(w.c.memory, 2);
  fill_memories(before);
  fill_memories(after);
  stage::PlannedHostWrites plan(w.c, w.in.host_jobs);
  plan.at_vertical_blank(t.cycles_to_ps(swap), after);

  std::mt19937 rng(4);
  const int64_t S = w.c.memory.face_size << w.c.widths.texel_frac;
  std::vector<stage::AddressToken> stim;
  for (int i = 0; i < 800; ++i) {
    stage::AddressToken a;
    a.slot = slot_of(i, 0, 0);
    a.sample = 0;
    for (int e = 0; e < 2; ++e) {
      dp::CubeAddress& ad = a.address[e];
      ad.face = static_cast<uint8_t>(i < 24 ? 5 : std::uniform_int_distribution<int>(0, 5)(rng));
      // Directed corners of the face first, then anywhere.
      ad.u = i < 24 ? (i % 2 ? S - 1 : 0) : std::uniform_int_distribution<int64_t>(0, S - 1)(rng);
      ad.v = i < 24 ? (i % 4 < 2 ? S - 1 : 0) : std::uniform_int_distribution<int64_t>(0, S - 1)(rng);
      ad.x = static_cast<int32_t>(ad.u >> w.c.widths.texel_frac);
      ad.y = static_cast<int32_t>(ad.v >> w.c.widths.texel_frac);
      ad.fx = static_cast<uint32_t>(ad.u & ((1 << w.c.widths.texel_frac) - 1));
      ad.fy = static_cast<uint32_t>(ad.v & ((1 << w.c.widths.texel_frac) - 1));
    }
    stim.push_back(a);
  }
  // The second half is driven only after the swap.
  std::unique_ptr<scm::DisplayMemoryBanks> dut;
  auto r = run_bench<scm::DisplayMemoryBanks>(w, stim, swap + 3000, &dut, swap + 10);
  check_flow(r, lat(w, dp::Stage::Fetch));
  // The host port took the job when the plan says and the banks swapped once, at the vertical blank.
  const auto& host = dut->host_port();
  ASSERT_EQ(host.timings().size(), 1u);
  EXPECT_EQ(host.timings()[0].start_ps, plan.timings()[0].start_ps);
  EXPECT_EQ(host.timings()[0].commit_ps, plan.timings()[0].commit_ps);
  EXPECT_EQ(dut->stage().swapper().swaps(), 1);
  EXPECT_EQ(dut->stage().swapper().front_select, 1u << (1 * w.c.memory.count + 1));
  int changed = 0;
  const uint64_t empty_word = dp::MemoryFormat(w.c.memory).empty_word();
  for (size_t i = 0; i < r.got.size(); ++i) {
    const dp::DisplayMemorySet& ref = i < r.phase_one ? before : after;
    for (int e = 0; e < 2; ++e) {
      const dp::CubeAddress& a = r.stimulus[i].address[e];
      const dp::BilinearTaps b = dp::bilinear_taps(a.u, a.v, w.c.widths.texel_frac, w.c.memory.face_size);
      const int32_t tx[4] = {b.x0, b.x1, b.x0, b.x1}, ty[4] = {b.y0, b.y0, b.y1, b.y1};
      EXPECT_EQ(r.got[i].wx[e], b.wx);
      EXPECT_EQ(r.got[i].wy[e], b.wy);
      for (int tap = 0; tap < 4; ++tap)
        for (int m = 0; m < w.c.memory.count; ++m) {
          const uint64_t want = ref.bank(e, m).read(a.face, tx[tap], ty[tap]);
          // A memory left out of the token (a face never written) must read empty there; memory 0's
          // words travel all the same (the waveform's probe).
          if ((r.got[i].held[e] >> m & 1u) || m == 0)
            ASSERT_EQ(r.got[i].words[e][tap][m], want) << "item " << i << " eye " << e << " tap " << tap << " memory " << m;
          else
            ASSERT_EQ(want, empty_word) << "memory " << m << " left out at item " << i << " eye " << e << " tap " << tap;
          if (i >= r.phase_one && want != before.bank(e, m).read(a.face, tx[tap], ty[tap])) ++changed;
        }
    }
  }
  EXPECT_GT(changed, 0) << "no read saw the swapped-in image";
}

TEST(ModuleBench, CompositionUnit) {
  World w;
  w.build();
  std::mt19937 rng(5);
  const dp::MemoryFormat f(w.c.memory);
  const uint32_t empty = f.empty_depth();
  const int N = w.c.memory.count;
  std::vector<stage::FetchToken> stim;
  for (int i = 0; i < 600; ++i) {
    stage::FetchToken t{};
    t.slot = slot_of(i, 0, 0);
    t.memories = static_cast<uint8_t>(N);
    t.taps = 4;
    for (int e = 0; e < 2; ++e) {
      t.wx[e] = std::uniform_int_distribution<uint32_t>(0, 255)(rng);
      t.wy[e] = std::uniform_int_distribution<uint32_t>(0, 255)(rng);
      for (int tap = 0; tap < 4; ++tap)
        for (int m = 0; m < N; ++m) {
          // Few depth values so ties are common; some empty, some all-empty quads.
          const int kind = i < 8 ? i % 4 : std::uniform_int_distribution<int>(0, 3)(rng);
          const uint32_t depth = kind == 0 ? empty : (kind == 1 ? 7u : std::uniform_int_distribution<uint32_t>(0, 9)(rng));
          const uint32_t color = std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng);
          t.words[e][tap][m] = (uint64_t{i < 4 ? empty : depth} << 32) | color;
        }
    }
    stim.push_back(t);
  }
  auto r = run_bench<scm::CompositionUnit>(w, stim, 2600);
  check_flow(r, lat(w, dp::Stage::Compose));
  const dp::CompositionParams cp(f, w.c.memory.background);
  for (size_t i = 0; i < r.got.size(); ++i)
    for (int e = 0; e < 2; ++e)
      for (int tap = 0; tap < 4; ++tap) {
        const uint64_t* words = r.stimulus[i].words[e][tap];
        ASSERT_EQ(r.got[i].tap_color[e][tap], dp::compose(words, N, cp).color) << "item " << i;
        // Independently: the smallest depth, the lowest memory on a tie, the background if all are empty.
        int best = 0;
        for (int m = 1; m < N; ++m)
          if ((words[m] >> 32) < (words[best] >> 32)) best = m;
        const uint32_t want = (words[best] >> 32) == empty ? cp.background : static_cast<uint32_t>(words[best]);
        EXPECT_EQ(r.got[i].tap_color[e][tap], want) << "item " << i;
      }
}

// The filter's bench, its module bound to the FIFO channels or (through_interfaces) to ForwardingFifos.
void filter_bench(bool through_interfaces) {
  World w;
  w.build();
  std::mt19937 rng(6);
  const int T = w.c.widths.texel_frac;
  const uint32_t W = 1u << T;
  std::vector<stage::ComposedToken> stim;
  for (int i = 0; i < 600; ++i) {
    stage::ComposedToken t{};
    t.slot = slot_of(i, 0, 0);
    for (int e = 0; e < 2; ++e) {
      // Directed: zero and maximal weights, saturated and black taps.
      t.wx[e] = i < 8 ? (i % 2 ? W - 1 : 0) : std::uniform_int_distribution<uint32_t>(0, W - 1)(rng);
      t.wy[e] = i < 8 ? (i % 4 < 2 ? W - 1 : 0) : std::uniform_int_distribution<uint32_t>(0, W - 1)(rng);
      for (int tap = 0; tap < 4; ++tap)
        t.tap_color[e][tap] = i < 8 ? (tap % 2 ? 0xffffffu & 0xffffff : 0) : std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng);
    }
    stim.push_back(t);
  }
  auto r = run_bench<scm::AntiAliasingFilter>(w, stim, 2600, nullptr, 0, through_interfaces);
  check_flow(r, lat(w, dp::Stage::Filter));
  if (through_interfaces) {
    EXPECT_GT(r.forwarded_calls, 2 * static_cast<int64_t>(stim.size())) << "the module must have called the forwarding channels";
    EXPECT_GT(r.forwarded_clock_calls, static_cast<int64_t>(stim.size())) << "the module must have read the forwarding clock";
    EXPECT_FALSE(r.clock_direct);
    EXPECT_EQ(r.processes, std::vector<std::string>{"dut.on_clock"}) << "a process of its own on another clock channel";
  } else {
    EXPECT_EQ(r.forwarded_calls, 0);
    EXPECT_TRUE(r.clock_direct) << "bound to a ClockGenerator, the module reads its cycle directly";
    EXPECT_TRUE(r.processes.empty()) << "bound to a ClockGenerator, the generator runs the module";
  }
  const dp::ChannelLayout L{dp::MemoryFormat(w.c.memory)};
  for (size_t i = 0; i < r.got.size(); ++i)
    for (int e = 0; e < 2; ++e) {
      const auto& in = r.stimulus[i];
      const uint32_t* c = in.tap_color[e];
      ASSERT_EQ(r.got[i].color[e], dp::bilinear_blend(c[0], c[1], c[2], c[3], in.wx[e], in.wy[e], T, L)) << "item " << i;
      // Golden: the exact bilinear value, rounded half up -> within half a code.
      const double fx = in.wx[e] / double(W), fy = in.wy[e] / double(W);
      for (int ch = 0; ch < 3; ++ch) {
        auto v = [&](uint32_t col) { return double((col >> (8 * (2 - ch))) & 255); };
        const double exact = (v(c[0]) * (1 - fx) + v(c[1]) * fx) * (1 - fy) + (v(c[2]) * (1 - fx) + v(c[3]) * fx) * fy;
        EXPECT_NEAR(double((r.got[i].color[e] >> (8 * (2 - ch))) & 255), exact, 0.5 + 1e-9) << "item " << i;
      }
    }
}

TEST(ModuleBench, AntiAliasingFilter) { filter_bench(false); }

// A stage bound to other channels with the FIFO and clock interfaces (not a
// FifoChannel or a ClockGenerator) takes the interfaces' path: the same pixels at the same clocks.
TEST(ModuleBench, AntiAliasingFilterThroughTheInterfaces) { filter_bench(true); }

// The video timing generator issues every active pixel of the run, in scan
// order, issue_lead clocks before its slot, with latch points per the policy.
TEST(ModuleBench, VideoTimingGenerator) {
  World w;
  w.c.pipeline.latch = dp::LatchPolicy::PerScanline;
  w.build();
  w.in.first_frame = 1;
  w.in.frames = 1;
  sc_set_time_resolution(1, SC_PS);
  const dp::VideoTiming t(w.c.timing);
  const dp::PipelineSchedule sched(w.c);
  const int64_t end = t.frame_start_cycle(2) + 10;
  scm::ClockGenerator gen = w.clock(end);
  scm::FifoChannel<stage::PixelSlot> out_fifo = w.fifo<stage::PixelSlot>("requests");
  scm::VideoTimingGenerator dut("dut", w.context());
  dut.clk(gen);
  dut.output(out_fifo);
  ResponseMonitor<stage::PixelSlot> mon("monitor", SIZE_MAX, 7);
  mon.clk(gen);
  mon.response_in(out_fifo);
  const int none = 0;
  BenchWaveform wave(gen, none, out_fifo.core().occupancy_ref());
  if (wave.file()) dut.trace(wave.file());
  sc_start(sc_time::from_value(static_cast<sc_time::value_type>(t.cycles_to_ps(end + 1))));
  const int W = w.c.timing.h_active, H = w.c.timing.v_active;
  ASSERT_EQ(mon.got.size(), static_cast<size_t>(W * H));
  for (size_t i = 0; i < mon.got.size(); ++i) {
    const auto& s = mon.got[i];
    const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
    ASSERT_EQ(s.frame, 1);
    ASSERT_EQ(s.x, x);
    ASSERT_EQ(s.y, y);
    ASSERT_EQ(s.eye_count, 2);
    ASSERT_EQ(s.slot_cycle, t.pixel_cycle(1, 0, x, y));
    ASSERT_EQ(s.latch, x == 0);
    ASSERT_EQ(mon.read_cycle[i], s.slot_cycle - sched.issue_lead() + 1);  // issued, visible one clock later
  }
  EXPECT_EQ(dut.stage().issue_stalls(), 0);
}

// Scan-out: each slot shows its pixel, converted to the panel's depth, at its
// photon time; a missing pixel is a counted underflow in the underflow
// colour; a pixel arriving after its slot is dropped and counted.
TEST(ModuleBench, HmdScanOut) {
  World w;
  w.c.pipeline.display_bits = 6;
  std::vector<std::pair<HmdFrame, stage::FrameReport>> frames;
  w.in.sink = [&frames](const HmdFrame& f, const stage::FrameReport& r) { frames.push_back({f, r}); };
  w.build();
  w.in.first_frame = 1;  // frame 0 starts at clock 0, before the bench's first clock
  w.in.frames = 1;
  sc_set_time_resolution(1, SC_PS);
  const dp::VideoTiming t(w.c.timing);
  const dp::PipelineSchedule sched(w.c);
  const int W = w.c.timing.h_active, H = w.c.timing.v_active;
  std::mt19937 rng(8);
  std::vector<stage::ColorToken> tokens;
  std::vector<int64_t> due;  // when the driver writes each token
  std::set<std::pair<int, int>> missing, late;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int64_t slot = t.pixel_cycle(1, 0, x, y);
      if (y == 5 && x >= 10 && x < 14) {
        missing.insert({x, y});  // never sent
        continue;
      }
      stage::ColorToken c{};
      c.slot = slot_of(0, x, y);
      c.slot.slot_cycle = slot;
      c.color[0] = std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng);
      c.color[1] = std::uniform_int_distribution<uint32_t>(0, 0xffffff)(rng);
      tokens.push_back(c);
      const bool is_late = y == 9 && x == W - 1;  // at a line's end: it cannot hold up the next pixels
      if (is_late) late.insert({x, y});
      due.push_back(is_late ? slot : slot - 3);  // late: written at its own slot, after scan-out needed it
    }
  const int64_t end = sched.swap_cycle(1) + 1;
  scm::ClockGenerator gen = w.clock(end);
  scm::FifoChannel<stage::ColorToken> in_fifo = w.fifo<stage::ColorToken>("colors");
  scm::HmdScanOut dut("dut", w.context());
  dut.clk(gen);
  dut.input(in_fifo);
  // A driver writing each token at its due clock.
  struct TimedDriver : ClockedBenchModule {
    TimedDriver(sc_module_name n, scm::FifoChannel<stage::ColorToken>& f, const std::vector<stage::ColorToken>& tk,
                const std::vector<int64_t>& d)
        : ClockedBenchModule(n), fifo(f), tokens(tk), due(d) {}
    void on_clock(int64_t cycle) override {
      if (next < tokens.size() && due[next] <= cycle && fifo.can_write()) fifo.write(tokens[next++], cycle);
    }
    scm::FifoChannel<stage::ColorToken>& fifo;
    const std::vector<stage::ColorToken>& tokens;
    const std::vector<int64_t>& due;
    size_t next = 0;
  } drv("driver", in_fifo, tokens, due);
  drv.clk(gen);
  const int none = 0;
  BenchWaveform wave(gen, in_fifo.core().occupancy_ref(), none);
  if (wave.file()) dut.trace(wave.file());
  sc_start(sc_time::from_value(static_cast<sc_time::value_type>(t.cycles_to_ps(end + 1))));
  ASSERT_EQ(frames.size(), 1u);
  const HmdFrame& f = frames[0].first;
  const stage::FrameReport& rep = frames[0].second;
  const dp::HmdScanOut scan(dp::MemoryFormat(w.c.memory), w.c.pipeline);
  const uint32_t bad = stage::underflow_color(6);
  size_t k = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int64_t photon = t.cycles_to_ps(t.pixel_cycle(1, 0, x, y)) + w.c.pipeline.photon_delay_ps;
      for (int e = 0; e < 2; ++e) EXPECT_EQ(f.photon_ps[f.index(e, x, y)], photon);
      if (missing.count({x, y})) {
        EXPECT_EQ(f.at(0, x, y), bad);
        continue;
      }
      const auto& tok = tokens[k++];
      if (late.count({x, y})) {
        EXPECT_EQ(f.at(0, x, y), bad) << x << "," << y;
        continue;
      }
      ASSERT_EQ(f.at(0, x, y), scan.to_display(tok.color[0])) << x << "," << y;
      ASSERT_EQ(f.at(1, x, y), scan.to_display(tok.color[1])) << x << "," << y;
    }
  // The late pixel's slot underflowed; the pixel itself was dropped in the blanking after it.
  EXPECT_EQ(rep.late_discarded, 1);
  EXPECT_EQ(rep.underflows, static_cast<int64_t>(missing.size()) + 1);
}
