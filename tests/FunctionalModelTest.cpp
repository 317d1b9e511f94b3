#include <gtest/gtest.h>

#include <map>

#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/DisplayMemoryFill.hpp"
#include "FrameFixtures.hpp"
#include "common/InputError.hpp"
#include "rtl_model/functional/FunctionalModel.hpp"

using namespace arp;
using namespace arp::dp;

namespace {

// The datapath applied pixel by pixel in the plainest way: the reference the
// functional model's vectorised passes must equal bit for bit.
// edge_taps: the bilinear pixels whose horizontal taps are one texel, at a face's first or last column, with a
// weight on the second (the model's passes weight it 0 and read the apron there: these pixels check it).
HmdFrame scalar_reference(const ArpConfig& c, const DisplayMemorySet& mem, const OrientationStream& o, int64_t frame,
                          int64_t* edge_taps = nullptr) {
  const VideoTiming t(c.timing);
  const LensVectorTable lens(c.lens, c.timing, c.widths.vec_frac);
  const AddressGeneratorParams ap(c.widths, c.memory.face_size);
  const RotateParams rp(c.widths);
  const MemoryFormat fmt(c.memory);
  const CompositionParams cp(fmt, c.memory.background);
  const ChannelLayout L(fmt);
  const HmdScanOut scan(fmt, c.pipeline);
  HmdFrame f;
  f.resize(lens.width(), lens.height(), lens.eyes(), false);
  f.display_bits = c.pipeline.display_bits;
  std::vector<uint64_t> w(static_cast<size_t>(mem.count()));
  const LatchRule rule(t, c.pipeline.latch, PipelineSchedule(c).orientation_lead());
  for (int e = 0; e < lens.eyes(); ++e)
    for (int y = 0; y < lens.height(); ++y)
      for (int x = 0; x < lens.width(); ++x) {
        const int64_t lc = rule.read_cycle(frame, e, x, y);
        const Mat3q M = quantise_rotation(o[o.index_at(t.cycles_to_ps(lc))].q, c.widths.mat_frac);
        const CubeAddress a = generate_address(rotate(M, lens.at(e, x, y), rp), ap);
        auto at = [&](int tx, int ty) {
          for (int m = 0; m < mem.count(); ++m) w[static_cast<size_t>(m)] = mem.bank(e, m).read(a.face, tx, ty);
          return compose(w.data(), mem.count(), cp).color;
        };
        uint32_t col;
        if (c.pipeline.aa == AaMode::Off) {
          col = at(a.x, a.y);
        } else {
          const BilinearTaps tp = bilinear_taps(a.u, a.v, c.widths.texel_frac, c.memory.face_size);
          if (edge_taps && tp.x1 == tp.x0 && tp.wx != 0) ++*edge_taps;
          col = bilinear_blend(at(tp.x0, tp.y0), at(tp.x1, tp.y0), at(tp.x0, tp.y1), at(tp.x1, tp.y1), tp.wx, tp.wy,
                               c.widths.texel_frac, L);
        }
        f.pixels[f.index(e, x, y)] = scan.to_display(col);
      }
  return f;
}

// A head turning fast (about 1000 deg/s about a tilted axis), 1 kHz samples.
OrientationStream fast_turn(const VideoTiming& t, int64_t frame) { return test::turning(t, frame, 1.0); }
void fill(DisplayMemorySet& mem) { test::fill_layered(mem); }

// fill() and then every further memory written too, each over its own pattern, with depths that tie
// across memories: the composition of four to eight memories (each count its own passes), and of more
// than eight (a count known only at run time). fill() alone writes at most three. The odd memories are
// written from the last face's last row back, so their tiles are taken out of table order (read through
// their tables, at any face size).
void fill_every_memory(DisplayMemorySet& mem) {
  fill(mem);
  const MemoryFormat& fmt = mem.format();
  const int S = fmt.face_size;
  for (int e = 0; e < mem.eyes(); ++e)
    for (int m = 3; m < mem.count(); ++m) {
      auto& b = mem.bank(e, m);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < S; ++j)
          for (int x = 0; x < S; ++x)
            if (const int f = m % 2 ? 5 - i : i, y = m % 2 ? S - 1 - j : j; (x + 2 * y + 3 * m) % (m - 1) != 0)
              b.write(f, x, y, fmt.pack_rgb8(20 * m, 255 - 30 * f, (x * 255) / S),
                      fmt.empty_depth() / 3 + static_cast<uint32_t>((x + y + m) % 3) - 1);
      b.commit();
      b.vblank();
      if (m % 2) {
        EXPECT_FALSE(b.front_tiles_in_order()) << "memory " << m;
      }
    }
}

// Every memory a whole cube written in order, at depths that tie across memories and cross between
// them: every bank's tiles in table order, so the several-memory passes read without the tile tables.
void fill_every_memory_in_order(DisplayMemorySet& mem) {
  const MemoryFormat& fmt = mem.format();
  const int S = fmt.face_size;
  for (int e = 0; e < mem.eyes(); ++e)
    for (int m = 0; m < mem.count(); ++m) {
      auto& b = mem.bank(e, m);
      for (int f = 0; f < 6; ++f)
        for (int y = 0; y < S; ++y)
          for (int x = 0; x < S; ++x)
            b.write(f, x, y, fmt.pack_rgb8(20 * m + 5 * e, 255 - 30 * f, (x * 255) / S),
                    fmt.empty_depth() / 3 + static_cast<uint32_t>((x + 2 * y + 5 * m) % 7) - 3);
      b.commit();
      b.vblank();
    }
}

// One memory (the single-memory passes), written from the last face's last row back: its tiles out of
// table order, read through its table.
void fill_one_memory_backwards(DisplayMemorySet& mem) {
  const MemoryFormat& fmt = mem.format();
  const int S = fmt.face_size;
  for (int e = 0; e < mem.eyes(); ++e) {
    auto& b = mem.bank(e, 0);
    for (int f = 5; f >= 0; --f)
      for (int y = S - 1; y >= 0; --y)
        for (int x = 0; x < S; ++x)
          b.write(f, x, y, fmt.pack_rgb8(40 * f + 5 * e, (y * 255) / S, (x * 255) / S), fmt.empty_depth() / 2);
    b.commit();
    b.vblank();
    EXPECT_FALSE(b.front_tiles_in_order()) << "eye " << e;
  }
}

enum class Fill { Layered, EveryMemory, EveryMemoryInOrder, OneMemoryBackwards };

void expect_bit_identical(const ArpConfig& c, const std::string& what, Fill how = Fill::Layered) {
  DisplayMemorySet mem(c.memory, c.timing.eyes);
  if (how == Fill::EveryMemory) fill_every_memory(mem);
  else if (how == Fill::EveryMemoryInOrder) fill_every_memory_in_order(mem);
  else if (how == Fill::OneMemoryBackwards) fill_one_memory_backwards(mem);
  else fill(mem);
  // Which read path the model's passes take for each eye: by arithmetic only where every memory was written
  // whole, in order (fill() writes memory 0 so, and the others sparsely).
  const bool in_order = how == Fill::EveryMemoryInOrder || (how == Fill::Layered && mem.count() == 1);
  for (int e = 0; e < mem.eyes(); ++e) {
    std::vector<std::vector<int32_t>> flat;
    EXPECT_EQ(FunctionalModel::eye_sources(mem, e, flat).dense, in_order) << what << ", eye " << e;
  }
  const FunctionalModel model(c);
  const OrientationStream o = fast_turn(model.timing(), 1);
  int64_t edge_taps = 0;
  const HmdFrame ref = scalar_reference(c, mem, o, 1, &edge_taps);
  // The turning head shows cube edges: a bilinear frame holds pixels whose taps meet a face's first or last
  // column (their count is the fixture's, not the model's).
  if (c.pipeline.aa == AaMode::Bilinear) {
    EXPECT_GT(edge_taps, 0) << what;
  }
  for (int threads : {1, 2}) {
    HmdFrame f;
    RenderOptions ro;
    ro.threads = threads;
    model.render(mem, o, 1, f, ro);
    ASSERT_EQ(f.pixels.size(), ref.pixels.size());
    size_t diff = 0;
    for (size_t i = 0; i < f.pixels.size(); ++i) diff += f.pixels[i] != ref.pixels[i];
    EXPECT_EQ(diff, 0u) << what << ", " << threads << " thread(s)";
  }
}

}  // namespace

TEST(FunctionalModel, BitIdenticalToPixelByPixelDatapathAtDefaults) { expect_bit_identical(ArpConfig{}, "defaults"); }

TEST(FunctionalModel, BitIdenticalAcrossConfigurations) {
  std::map<std::string, ArpConfig> cases;
  ArpConfig c = test::small_display(ArpConfig{});
  cases["small bilinear"] = c;
  c.pipeline.aa = AaMode::Off;
  cases["nearest"] = c;
  c = test::small_display(ArpConfig{});
  c.widths.divider = DividerKind::Exact;
  cases["exact divider"] = c;
  c = test::small_display(ArpConfig{});
  c.widths.vec_frac = c.widths.mat_frac = c.widths.rot_frac = 20;  // too wide for the tabulated reciprocal
  c.widths.recip_index_bits = 10;
  c.widths.recip_frac_bits = 24;
  c.widths.quot_frac = 24;
  c.widths.texel_frac = 12;
  cases["wide, no reciprocal table"] = c;
  c = test::small_display(ArpConfig{});
  c.widths.vec_frac = 7;
  c.widths.mat_frac = 6;
  c.widths.rot_frac = 8;
  c.widths.recip_index_bits = 3;
  c.widths.recip_frac_bits = 8;
  c.widths.newton_steps = 0;
  c.widths.quot_frac = 9;
  c.widths.texel_frac = 3;
  c.widths.rot_rounding = c.widths.div_rounding = c.widths.texel_rounding = Rounding::HalfEven;
  cases["narrow, half-even"] = c;
  c = test::small_display(ArpConfig{});
  c.memory = MemoryConfig{3, 100, 5, 6, 5, 12, {0, 0, 40}};
  c.pipeline.display_bits = 6;
  c.widths.newton_steps = 2;
  cases["565 colour, 100-texel faces, 3 memories"] = c;
  c = test::small_display(ArpConfig{});
  c.timing.eyes = 1;
  c.pipeline.latch = LatchPolicy::PerPixel;
  c.pipeline.latch_lead_cycles = 37;
  c.lens.k = {1.0, 0.22, 0.24, 0.0};
  cases["mono, per-pixel latch, distortion"] = c;
  c = test::small_display(ArpConfig{});
  c.timing.eye_scan = EyeScan::SideBySide;
  c.timing.fields_per_frame = 2;
  c.pipeline.latch = LatchPolicy::PerField;
  c.lens.center_offset_px = 9;
  cases["side-by-side, interlaced, per-field latch"] = c;
  c = test::small_display(ArpConfig{});
  c.pipeline.latch = LatchPolicy::PerFrame;
  c.memory.count = 16;
  c.memory.face_size = 64;
  cases["16 memories, per-frame latch"] = c;
  // One memory: its own passes. The blend sums in 32 bits where dp::blend_fits_32 (8-bit channels up to
  // texel_frac 12), in 64 otherwise.
  c = test::small_display(ArpConfig{});
  c.memory.count = 1;
  cases["one memory, bilinear"] = c;
  c.widths.texel_frac = 13;
  c.widths.quot_frac = 16;
  cases["one memory, bilinear, texel_frac 13 (64-bit blend)"] = c;
  c = test::small_display(ArpConfig{});
  c.memory.count = 1;
  c.memory.red_bits = 16;
  c.memory.green_bits = c.memory.blue_bits = 8;
  c.widths.texel_frac = 9;
  cases["one memory, 16-bit red, texel_frac 9 (64-bit blend)"] = c;
  c = test::small_display(ArpConfig{});
  c.memory.count = 1;
  c.pipeline.aa = AaMode::Off;
  cases["one memory, nearest"] = c;
  // Two, three (above) and four memories (the defaults): loads, then composition in vectors.
  c = test::small_display(ArpConfig{});
  c.memory.count = 2;
  cases["two memories, bilinear"] = c;
  c.pipeline.aa = AaMode::Off;
  cases["two memories, nearest"] = c;
  c.memory.count = 3;
  cases["three memories, nearest"] = c;
  // The rotation's and the address generator's 64-bit lanes, for configurations whose values do not fit 32
  // bits (the lens vectors and matrix entries' sums reach 2^32; (q + 1) S reaches 2^34); the defaults take
  // the 32-bit lanes.
  c = test::small_display(ArpConfig{});
  EXPECT_TRUE(FunctionalModel(c).rotates_in_32_bits());
  EXPECT_TRUE(FunctionalModel(c).addresses_in_32_bits());
  c.widths.vec_frac = c.widths.mat_frac = 16;
  EXPECT_FALSE(FunctionalModel(c).rotates_in_32_bits());
  EXPECT_TRUE(FunctionalModel(c).addresses_in_32_bits());
  cases["16-bit lens and matrix fractions (64-bit rotation lanes)"] = c;
  c = test::small_display(ArpConfig{});
  c.widths.quot_frac = 24;
  EXPECT_TRUE(FunctionalModel(c).rotates_in_32_bits());
  EXPECT_FALSE(FunctionalModel(c).addresses_in_32_bits());
  cases["24-bit quotients (64-bit address lanes)"] = c;
  for (const auto& [name, cfg] : cases) expect_bit_identical(cfg, name);
  // One memory whose tiles are out of table order (read through its table; the cases above read by arithmetic).
  for (const AaMode aa : {AaMode::Bilinear, AaMode::Off}) {
    c = test::small_display(ArpConfig{});
    c.memory.count = 1;
    c.memory.face_size = 128;
    c.pipeline.aa = aa;
    expect_bit_identical(c, std::string("one memory written backwards, ") + (aa == AaMode::Off ? "nearest" : "bilinear"),
                         Fill::OneMemoryBackwards);
  }
  // Lines of several of the model's per-thread chunks (128 pixels, FunctionalModel::render_impl), the last
  // partial; the small display above has two. One memory (its own passes), two and four (whose loads look
  // ahead within a chunk, starting again in each), both filters.
  for (const int count : {1, 2, 4})
    for (const AaMode aa : {AaMode::Bilinear, AaMode::Off}) {
      c = ArpConfig{};
      c.timing = dp::VideoTimingConfig::mode(2, {700, 8, 16, 16}, {12, 2, 2, 6}, 1'400'000);
      c.memory.count = count;
      c.memory.face_size = 128;
      c.pipeline.aa = aa;
      expect_bit_identical(c, "700-pixel lines, " + std::to_string(count) + " memories written in order, " +
                                  (aa == AaMode::Off ? "nearest" : "bilinear"),
                           Fill::EveryMemoryInOrder);
    }
  // Every memory holding something: four to eight (the fixed-count passes, up to the composition unit's
  // eight inputs) and eleven (the run-time count); with the tiles where writes put them, and with every
  // memory's tiles in table order (read without the tables). Faces of 128 texels (4 x 4 tiles): writing eleven
  // memories' cubes of 512 took most of this test's time, and the 160 x 120 display reads a fraction of them.
  for (const int count : {2, 4, 5, 6, 7, 8, 11})
    for (const AaMode aa : {AaMode::Bilinear, AaMode::Off})
      for (const Fill how : {Fill::EveryMemory, Fill::EveryMemoryInOrder}) {
        if (count == 2 && how == Fill::EveryMemory) continue;  // (fill() covers two memories written sparsely)
        c = test::small_display(ArpConfig{});
        c.memory.count = count;
        c.memory.face_size = 128;
        c.pipeline.aa = aa;
        expect_bit_identical(c,
                             std::to_string(count) + " memories written" + (how == Fill::EveryMemoryInOrder ? " in order, " : ", ") +
                                 (aa == AaMode::Off ? "nearest" : "bilinear"),
                             how);
      }
}

namespace {
// The calibration colour that covers most of an eye's image.
int dominant_face(const HmdFrame& f, const MemoryFormat& fmt) {
  std::array<int, 6> counts{};
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      for (int face = 0; face < 6; ++face) {
        const auto& c = host::calibration_face_colors()[static_cast<size_t>(face)];
        counts[static_cast<size_t>(face)] += f.at(0, x, y) == fmt.pack_rgb8(c[0], c[1], c[2]);
      }
  return static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
}
}  // namespace

TEST(FunctionalModel, CalibrationFramesShowTheExpectedFaces) {
  const ArpConfig c;
  const FunctionalModel model(c);
  DisplayMemorySet mem(c.memory, 2);
  host::load_into_memories(mem, 0, host::make_calibration_pattern(512), host::far_depth(mem.format()));
  const struct { double yaw, pitch; int face; } cases[] = {
      {0, 0, kNegZ}, {90, 0, kNegX}, {180, 0, kPosZ}, {270, 0, kPosX}, {-90, 0, kPosX}, {0, 90, kPosY}, {0, -90, kNegY}};
  for (const auto& k : cases) {
    HmdFrame f;
    model.render(mem, OrientationStream::constant(from_yaw_pitch_roll_deg(k.yaw, k.pitch, 0)), 0, f);
    EXPECT_EQ(dominant_face(f, mem.format()), k.face) << "yaw " << k.yaw << " pitch " << k.pitch;
    // Infinitely far content, no lens offset: both eyes see the same image.
    EXPECT_TRUE(std::equal(f.pixels.begin(), f.pixels.begin() + 640 * 480, f.pixels.begin() + 640 * 480));
  }
}

TEST(FunctionalModel, LatchPolicyDecidesWhereANewOrientationTakesEffect) {
  ArpConfig c = test::small_display(ArpConfig{});
  c.pipeline.aa = AaMode::Off;
  DisplayMemorySet mem(c.memory, 2);
  host::load_into_memories(mem, 0, host::make_calibration_pattern(512), host::far_depth(mem.format()));
  const VideoTiming t(c.timing);
  // The head snaps from yaw 0 to yaw 40 just as pixel (70, 50) of frame 0
  // enters the orientation matrix unit, the schedule's lead before its slot.
  const int64_t lead = PipelineSchedule(c).orientation_lead();
  ASSERT_GT(lead, 0);
  const int64_t change = t.cycles_to_ps(t.pixel_cycle(0, 0, 70, 50) - lead);
  const OrientationStream o({{0, from_yaw_pitch_roll_deg(0, 0, 0)}, {change, from_yaw_pitch_roll_deg(40, 0, 0)}}, "t");
  const OrientationStream before = OrientationStream::constant(from_yaw_pitch_roll_deg(0, 0, 0));
  const OrientationStream after = OrientationStream::constant(from_yaw_pitch_roll_deg(40, 0, 0));
  auto render = [&](LatchPolicy p, const OrientationStream& s) {
    c.pipeline.latch = p;
    HmdFrame f;
    FunctionalModel(c).render(mem, s, 0, f);
    return f;
  };
  const HmdFrame b = render(LatchPolicy::PerFrame, before), a = render(LatchPolicy::PerFrame, after);
  auto same_row_part = [](const HmdFrame& x, const HmdFrame& y, int row, int x0, int x1) {
    for (int i = x0; i < x1; ++i)
      if (x.at(0, i, row) != y.at(0, i, row)) return false;
    return true;
  };
  const HmdFrame pf = render(LatchPolicy::PerFrame, o);
  EXPECT_EQ(pf.pixels, b.pixels);  // latched once at the frame start
  const HmdFrame pl = render(LatchPolicy::PerScanline, o);
  EXPECT_TRUE(same_row_part(pl, b, 50, 0, 160));  // line 50 latched before the change
  EXPECT_TRUE(same_row_part(pl, a, 51, 0, 160));
  EXPECT_TRUE(same_row_part(pl, b, 0, 0, 160));
  const HmdFrame pp = render(LatchPolicy::PerPixel, o);
  EXPECT_TRUE(same_row_part(pp, b, 50, 0, 70));
  EXPECT_TRUE(same_row_part(pp, a, 50, 70, 160));
  EXPECT_FALSE(same_row_part(pp, b, 50, 70, 160));
}

TEST(FunctionalModel, PhotonTimesFollowTheScan) {
  const ArpConfig c;
  const FunctionalModel model(c);
  DisplayMemorySet mem(c.memory, 2);
  HmdFrame f;
  RenderOptions ro;
  ro.photon_times = true;
  model.render(mem, OrientationStream::constant(Quat{}), 2, f, ro);
  const VideoTiming t(c.timing);
  EXPECT_EQ(f.photon_ps[f.index(0, 0, 0)], t.cycles_to_ps(840000));
  EXPECT_EQ(f.photon_ps[f.index(1, 639, 479)], t.cycles_to_ps(840000 + 479 * 800 + 639));
  for (int y = 0; y < 480; ++y)
    for (int x = 1; x < 640; ++x) ASSERT_GT(f.photon_ps[f.index(0, x, y)], f.photon_ps[f.index(0, x - 1, y)]);
  // An empty scene shows the background everywhere.
  for (uint32_t p : f.pixels) ASSERT_EQ(p, 0u);
}

TEST(FunctionalModel, RejectsMismatchedMemoriesAndBadConfigurations) {
  const ArpConfig c;
  const FunctionalModel model(c);
  MemoryConfig other = c.memory;
  other.face_size = 256;
  DisplayMemorySet wrong(other, 2);
  HmdFrame f;
  EXPECT_THROW(model.render(wrong, OrientationStream::constant(Quat{}), 0, f), InputError);
  DisplayMemorySet mono(c.memory, 1);
  EXPECT_THROW(model.render(mono, OrientationStream::constant(Quat{}), 0, f), InputError);
  ArpConfig bad = c;
  bad.lens.fov_deg = 180.0;
  EXPECT_THROW(FunctionalModel{bad}, InputError);
}
