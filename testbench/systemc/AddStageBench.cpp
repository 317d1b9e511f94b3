// Adding a stage, as an architect would: one new stage (RegisterSlice.hpp)
// and one line of wiring -- its type in the pipeline's StageList. The
// detailed model elaborated from that list has one more module and FIFO, a
// schedule one clock deeper, frames and photon times identical to the
// functional model's, and an orientation-sample -> photon latency exactly one
// clock longer (the register is read one clock earlier).
#include <gtest/gtest.h>

#include <map>

#include "BenchSupport.hpp"
#include "RegisterSlice.hpp"
#include "rtl_model/systemc/ArpPipelineTop.hpp"

using namespace arp;
using namespace sc_core;

namespace {

// The one line of wiring: the standard list with the slice after the address generator.
using WithSlice = scm::StageList<scm::VideoTimingGenerator, scm::LensVectorTable, scm::OrientationMatrixUnit,
                                 scm::CubeFaceAddressGenerator, bench::AddressRegisterSlice, scm::DisplayMemoryBanks,
                                 scm::CompositionUnit, scm::AntiAliasingFilter, scm::HmdScanOut>;

}  // namespace

TEST(AddStage, ARegisterSliceAddsOneClockAndChangesNoPixel) {
  dp::ArpConfig c = bench::small_config();
  c.timing.pixel_clock_hz = 1'000'000;  // 1 us clocks: latencies in whole picoseconds per clock
  c.pipeline.latch = dp::LatchPolicy::PerScanline;
  dp::DisplayMemorySet mem(c.memory, c.timing.eyes), ref_mem(c.memory, c.timing.eyes);
  bench::fill_memories(mem);
  bench::fill_memories(ref_mem);
  // One sample at every pixel clock, all the same orientation: reading the
  // register a clock earlier changes the sample (and its time), never the image.
  const dp::VideoTiming t(c.timing);
  std::vector<dp::OrientationSample> samples;
  const dp::Quat q = dp::from_yaw_pitch_roll_deg(30, 10, 0);
  for (int64_t n = t.frame_start_cycle(0); n < t.frame_start_cycle(4); ++n) samples.push_back({t.cycles_to_ps(n), q});
  const dp::OrientationStream stream(samples, "a sample every clock");

  stage::TimedInputs in = bench::inputs(c, mem, stream, 1, 2);
  stage::TimedInputs ref_in = in;
  ref_in.memories = &ref_mem;
  const auto want = bench::functional_frames(ref_in);

  // The schedule comes from the list: one clock deeper before the slice, unchanged after it.
  const dp::PipelineSchedule standard = scm::ArpStages::schedule(c), sliced = WithSlice::schedule(c);
  EXPECT_EQ(sliced.issue_lead(), standard.issue_lead() + 1);
  EXPECT_EQ(sliced.orientation_lead(), standard.orientation_lead() + 1);
  EXPECT_EQ(sliced.stage_to_scanout(dp::Stage::Fetch), standard.stage_to_scanout(dp::Stage::Fetch));

  std::map<int64_t, bench::CollectedFrame> got;
  in.sink = [&got](const HmdFrame& f, const stage::FrameReport& r) { got[r.frame] = {f, r}; };
  scm::claim_simulation();
  scm::DetailedPipeline<WithSlice> top("arp", in);
  sc_start(scm::sim_time(top.window().end_ps + 1, top.window().base_ps));

  ASSERT_EQ(got.size(), 2u);
  for (const auto& [frame, w] : want) {
    const auto& g = got.at(frame);
    EXPECT_EQ(g.frame.pixels, w.frame.pixels) << "frame " << frame;
    EXPECT_EQ(g.frame.photon_ps, w.frame.photon_ps) << "frame " << frame;
    EXPECT_EQ(g.report.underflows, 0);
    // Exactly one clock (1 us) more from the sample to the photon, for every pixel's summary.
    EXPECT_EQ(g.report.latency_min_ps, w.report.latency_min_ps + 1'000'000) << "frame " << frame;
    EXPECT_EQ(g.report.latency_median_ps, w.report.latency_median_ps + 1'000'000) << "frame " << frame;
    EXPECT_EQ(g.report.latency_max_ps, w.report.latency_max_ps + 1'000'000) << "frame " << frame;
  }
  // Measured in the simulation: the slice held every pixel exactly one clock; one more FIFO.
  const auto& slice = top.chain().module<4>().stage().stats();
  EXPECT_EQ(slice.pixels, 2 * c.timing.h_active * c.timing.v_active);
  EXPECT_EQ(slice.min_cycles, 1);
  EXPECT_EQ(slice.max_cycles, 1);
  const auto fifos = top.fifo_stats(top.window().end_cycle);
  ASSERT_EQ(fifos.size(), 8u);
  EXPECT_EQ(fifos[4].first, "registered_addresses");
}
