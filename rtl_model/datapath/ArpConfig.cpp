#include "ArpConfig.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

#include "CubeFaceAddressGenerator.hpp"
#include "common/InputError.hpp"
#include "PipelineSchedule.hpp"
#include "TileMap.hpp"

namespace arp::dp {

const EnumNames<EyeScan>& eye_scan_names() {
  static const EnumNames<EyeScan> n{{EyeScan::Lockstep, "lockstep"}, {EyeScan::SideBySide, "side_by_side"}};
  return n;
}
const EnumNames<LatchPolicy>& latch_policy_names() {
  static const EnumNames<LatchPolicy> n{{LatchPolicy::PerFrame, "frame"}, {LatchPolicy::PerField, "field"}, {LatchPolicy::PerScanline, "scanline"}, {LatchPolicy::PerPixel, "pixel"}};
  return n;
}
const EnumNames<DividerKind>& divider_names() {
  static const EnumNames<DividerKind> n{{DividerKind::ReciprocalLut, "lut"}, {DividerKind::Exact, "exact"}};
  return n;
}
const EnumNames<AaMode>& aa_names() {
  static const EnumNames<AaMode> n{{AaMode::Off, "off"}, {AaMode::Bilinear, "bilinear"}};
  return n;
}
const char* stage_key(Stage s) {
  static const char* const keys[kStageCount] = {"lens", "rotate", "address", "fetch", "compose", "filter", "scanout"};
  return keys[static_cast<size_t>(s)];
}

namespace {

// The timed keys of one stage, from the stage list (two per stage).
void add_stage_timing(ParameterTable<ArpConfig>& t, Stage s, const char* what) {
  const size_t i = static_cast<size_t>(s);
  const std::string k = std::string("timed.") + stage_key(s);
  t.number(k + "_latency", [i](auto& c) -> auto& { return c.timed.stage[i].latency_cycles; }, 1, 64, "clocks",
           std::string(what) + ": pixel clocks from taking a pixel to the next stage seeing it (its register stages, "
                                "including the output FIFO's register)");
  t.number(k + "_logic_ps", [i](auto& c) -> auto& { return c.timed.stage[i].logic_delay_ps; }, 0, 1'000'000'000, "ps",
           std::string(what) + ": combinational delay of its arithmetic; divided over its register stages it must fit "
                                "one pixel clock period");
}

ParameterTable<ArpConfig> make_parameters() {
  ParameterTable<ArpConfig> t;
  // display: video timing (VideoTiming)
  t.number("display.eyes", [](auto& c) -> auto& { return c.timing.eyes; }, 1, 2, "",
           "2 = stereo (one lens table and one set of display memories per eye), 1 = mono");
  t.choice("display.eye_scan", [](auto& c) -> auto& { return c.timing.eye_scan; }, eye_scan_names(),
           "lockstep: both eyes' panels scanned simultaneously (same cycle for the same pixel); side_by_side: one "
           "panel, each line scans the left eye's pixels then the right eye's");
  t.number("display.h_active", [](auto& c) -> auto& { return c.timing.h_active; }, 1, 8192, "px",
           "active pixels per line, per eye");
  t.number("display.h_front_porch", [](auto& c) -> auto& { return c.timing.h_front_porch; }, 0, 8192, "clocks",
           "horizontal blanking after the active pixels");
  t.number("display.h_sync", [](auto& c) -> auto& { return c.timing.h_sync; }, 0, 8192, "clocks", "horizontal sync");
  t.number("display.h_back_porch", [](auto& c) -> auto& { return c.timing.h_back_porch; }, 0, 8192, "clocks",
           "horizontal back porch; total line = active + porches + sync (800 by default)");
  t.number("display.v_active", [](auto& c) -> auto& { return c.timing.v_active; }, 1, 8192, "lines", "active lines per eye");
  t.number("display.v_front_porch", [](auto& c) -> auto& { return c.timing.v_front_porch; }, 0, 8192, "lines",
           "vertical blanking after the active lines");
  t.number("display.v_sync", [](auto& c) -> auto& { return c.timing.v_sync; }, 0, 8192, "lines", "vertical sync");
  t.number("display.v_back_porch", [](auto& c) -> auto& { return c.timing.v_back_porch; }, 0, 8192, "lines",
           "vertical back porch; total frame = active + porches + sync (525 lines by default)");
  t.number("display.pixel_clock_hz", [](auto& c) -> auto& { return c.timing.pixel_clock_hz; }, 1000, 100'000'000'000,
           "Hz", "pixel clock; 25.175 MHz / (800 x 525) = 59.94 Hz");
  t.number("display.fields_per_frame", [](auto& c) -> auto& { return c.timing.fields_per_frame; }, 1, 2, "",
           "1 progressive; 2 interlaced: even lines in field 0, odd lines in field 1, each field half a frame (the "
           "frame's clock count must be even)");
  // lens: lens vector table (LensVectorTable)
  t.number("lens.fov_deg", [](auto& c) -> auto& { return c.lens.fov_deg; }, 0.001, 179.999, "deg",
           "horizontal field of view of one eye's undistorted mapping");
  t.number("lens.k", [](auto& c) -> auto& { return c.lens.k; }, -100, 100, "",
           "radial distortion polynomial scale(r) = k0 + k1 r^2 + k2 r^4 + k3 r^6, r in half-widths from the lens "
           "centre; the scale must stay positive over the panel ([1, 0.22, 0.24, 0] is DK1-like)");
  t.number("lens.center_offset_px", [](auto& c) -> auto& { return c.lens.center_offset_px; }, -4096, 4096, "px",
           "lens centre moved toward the nose (left eye right, right eye left); less than half of display.h_active in "
           "magnitude");
  // datapath: widths, rounding and division
  t.number("datapath.vec_frac", [](auto& c) -> auto& { return c.widths.vec_frac; }, 1, 28, "bits",
           "lens vectors: signed Q1.vec_frac (vec_frac + 2 bits)");
  t.number("datapath.mat_frac", [](auto& c) -> auto& { return c.widths.mat_frac; }, 1, 28, "bits",
           "orientation matrix entries: signed Q1.mat_frac, saturating");
  t.number("datapath.rot_frac", [](auto& c) -> auto& { return c.widths.rot_frac; }, 1, 28, "bits",
           "rotated vector: signed Q1.rot_frac, saturating");
  t.choice("datapath.rot_rounding", [](auto& c) -> auto& { return c.widths.rot_rounding; }, rounding_names(),
           "rounding of the matrix x vector products to rot_frac");
  t.choice("datapath.divider", [](auto& c) -> auto& { return c.widths.divider; }, divider_names(),
           "division by the major component: reciprocal unit (leading-one normaliser, table, Newton-Raphson, one "
           "multiply per quotient) or an exact divider");
  t.number("datapath.recip_index_bits", [](auto& c) -> auto& { return c.widths.recip_index_bits; }, 1, 16, "bits",
           "the reciprocal table has 2^bits entries, indexed by the mantissa bits below the leading one");
  t.number("datapath.recip_frac_bits", [](auto& c) -> auto& { return c.widths.recip_frac_bits; }, 4, 30, "bits",
           "reciprocal table entries and refined reciprocal: unsigned Q1.recip_frac");
  t.number("datapath.newton_steps", [](auto& c) -> auto& { return c.widths.newton_steps; }, 0, 4, "",
           "Newton-Raphson refinements y <- y(2 - m y) after the table");
  t.number("datapath.quot_frac", [](auto& c) -> auto& { return c.widths.quot_frac; }, 2, 30, "bits",
           "face coordinate sc/|ma|: signed Q1.quot_frac, clamped to +-1");
  t.choice("datapath.div_rounding", [](auto& c) -> auto& { return c.widths.div_rounding; }, rounding_names(),
           "rounding in the reciprocal unit and of the quotients");
  t.number("datapath.texel_frac", [](auto& c) -> auto& { return c.widths.texel_frac; }, 0, 16, "bits",
           "sub-texel bits of the texel-space position: the bilinear weights (at least 1 with bilinear)");
  t.choice("datapath.texel_rounding", [](auto& c) -> auto& { return c.widths.texel_rounding; }, rounding_names(),
           "rounding of (q + 1)/2 x S to texel_frac bits");
  // memory: display memories (DisplayMemoryBank)
  t.number("memory.count", [](auto& c) -> auto& { return c.memory.count; }, 1, 16, "",
           "display memories per eye (memory 0 is the most often updated and wins depth ties)");
  t.number("memory.face_size", [](auto& c) -> auto& { return c.memory.face_size; }, 1, 16384, "texels",
           "S: each cube face is S x S texels");
  t.number("memory.red_bits", [](auto& c) -> auto& { return c.memory.red_bits; }, 1, 16, "bits",
           "red channel width (red + green + blue at most 32)");
  t.number("memory.green_bits", [](auto& c) -> auto& { return c.memory.green_bits; }, 1, 16, "bits", "green channel width");
  t.number("memory.blue_bits", [](auto& c) -> auto& { return c.memory.blue_bits; }, 1, 16, "bits", "blue channel width");
  t.number("memory.depth_bits", [](auto& c) -> auto& { return c.memory.depth_bits; }, 1, 32, "bits",
           "depth code width; the code 2^bits - 1 is reserved for \"empty\" (1 bit: a written flag, for one memory)");
  t.number("memory.background", [](auto& c) -> auto& { return c.memory.background; }, 0, 255, "RGB8",
           "colour shown where every memory is empty");
  t.number("memory.faces", [](auto& c) -> auto& { return c.memory.faces; }, 0, 1, "",
           "the cube faces each memory has, +X -X +Y -Y +Z -Z: 1 present, 0 absent (no storage, reads empty, the "
           "host's writes to it lost and counted; arpsim plan leaves out the faces no object reaches)");
  t.text_list("memory.tiles", [](auto& c) -> auto& { return c.memory.tiles; }, 16, "0123456789abcdefABCDEF*-/:", "",
              "the 32 x 32 tiles each memory holds, one string per memory (none: every tile): the face size it was listed for and "
              "a colon, then six fields separated by '/', "
              "faces +X -X +Y -Y +Z -Z, each \"*\" (every tile), \"-\" (none) or hex digits, tile k = ty x T + tx at bit k % 4 of "
              "digit k / 4 (T tiles a row); a texel drawn on a tile a memory does not hold is lost and counted, as on an absent "
              "face (arpsim plan writes the tiles its scene's motion can draw on; docs/planning.md)");
  t.number_list("memory.tile_pool", [](auto& c) -> auto& { return c.memory.tile_pool; }, 16, 0, int64_t{1} << 24, "tiles",
                "a tile pool per memory, one number per memory (none: no pool): that many 32 x 32 tile slots shared by the "
                "memory's two buffers, each buffer's tile table naming its tiles' slots; a tile first drawn on while every "
                "slot is taken gets none until its buffer is cleared, its texels lost and counted; 0: no pool for that memory; "
                "at most twice the tiles of the memory's faces (its two buffers' worth) "
                "(arpsim plan sizes them from the motion; docs/planning.md)");
  t.number("memory.update_frames", [](auto& c) -> auto& { return c.memory.update_frames; }, 1, MemoryConfig::kMaxUpdateFrames,
           "frames", "display frames between host updates of memory 0 (object-level priority rendering)");
  t.number("memory.update_ratio", [](auto& c) -> auto& { return c.memory.update_ratio; }, 1, 64, "",
           "each next memory is updated this many times less often (Regan & Pose: 2, harmonic rates)");
  t.number("memory.threshold_deg", [](auto& c) -> auto& { return c.memory.threshold_deg; }, 0.0, 90.0, "deg",
           "priority rendering's threshold angle theta_t: an object is re-rendered before its image moves this far "
           "(0: one texel at a face's centre, 90 deg / face_size; arpsim plan records the one it planned for; "
           "--threshold-deg overrides)");
  t.text_list("memory.assignment", [](auto& c) -> auto& { return c.memory.assignment; }, 65536, "", "",
              "the memories objects are kept in, one string per object name (none: the priority rule alone): \"name: m\" "
              "pins every object of that name to memory m, \"name: a-b\" keeps them in memories a to b (0 the fastest); the "
              "rule's choice is clamped to that range, and the tile and pool guards may still send one faster (arpsim plan "
              "writes the memories its rule gives each object over the motion; docs/planning.md)");
  t.number("memory.region_size_m", [](auto& c) -> auto& { return c.memory.region_size_m; }, 0.0, 100000.0, "m",
           "region priority rendering (Chow, Pose & Regan 2005) with a walk: the world cut into square columns of this size, "
           "each region's objects in the memory of its ring around the user's region; 0: object-level priority "
           "(--regions overrides; arpsim plan weighs it)");
  t.number("memory.region_margin_m", [](auto& c) -> auto& { return c.memory.region_margin_m; }, 0.0, 100000.0, "m",
           "region priority rendering: how far into a new region the user goes before regions are re-assigned, less than "
           "half the region size (--margin overrides)");
  // pipeline: latch, filtering and scan-out
  t.choice("pipeline.latch", [](auto& c) -> auto& { return c.pipeline.latch; }, latch_policy_names(),
           "when the orientation register is sampled: at the start of the frame, of the field, of each scanline, or "
           "for every pixel");
  t.number("pipeline.latch_lead_cycles", [](auto& c) -> auto& { return c.pipeline.latch_lead_cycles; }, 0,
           1'000'000'000, "clocks",
           "extra lead: the register is sampled this many pixel clocks before the latch-point pixel enters the "
           "orientation matrix unit (the total lead adds the unit's distance to scan-out, 14 clocks by default)");
  t.choice("pipeline.aa", [](auto& c) -> auto& { return c.pipeline.aa; }, aa_names(),
           "anti-aliasing: nearest texel, or bilinear over four taps each composited first");
  t.number("pipeline.display_bits", [](auto& c) -> auto& { return c.pipeline.display_bits; }, 1, 10, "bits",
           "bits per channel at the HMD; memory colour is rescaled with rounding");
  t.number("pipeline.photon_delay_ps", [](auto& c) -> auto& { return c.pipeline.photon_delay_ps; }, 0,
           1'000'000'000'000, "ps", "panel response: photon time = scan-out time + this");
  // timed: hardware timing of the cycle models, two keys per stage in data-flow order
  static const char* const what[kStageCount] = {
      "lens vector table",         "orientation matrix unit", "cube-face address generator", "display memory read",
      "composition unit",          "anti-aliasing filter",    "HMD scan-out (the pixel is taken this many clocks before its slot)"};
  for (int s = 0; s < kStageCount; ++s) add_stage_timing(t, static_cast<Stage>(s), what[s]);
  t.number("timed.fifo_depth", [](auto& c) -> auto& { return c.timed.fifo_depth; }, 1, 4096, "tokens",
           "tokens each inter-stage FIFO holds; at least issue_slack_cycles + 2 (the scan-out FIFO holds slack + 1 "
           "and has no bypass)");
  t.number("timed.issue_slack_cycles", [](auto& c) -> auto& { return c.timed.issue_slack_cycles; }, 0, 4096, "clocks",
           "the timing generator issues each pixel this much earlier than the latencies need; the slack waits in the "
           "scan-out FIFO and absorbs stalls");
  t.number("timed.host_clock_hz", [](auto& c) -> auto& { return c.timed.host_clock_hz; }, 1000, 100'000'000'000, "Hz",
           "clock of the host's write port into display memory");
  t.number("timed.host_texels_per_cycle", [](auto& c) -> auto& { return c.timed.host_texels_per_cycle; }, 1, 1 << 20,
           "texels", "texels the write port stores per host clock (its bandwidth)");
  // host: the simulated rendering engine of priority rendering (host::RenderEngine)
  t.number("host.triangles_per_s", [](auto& c) -> auto& { return c.host.triangles_per_s; }, 1.0, 1e15, "triangles/s",
           "the simulated rendering engine's triangle rate: each triangle counts once per cube face it is sent to, per "
           "eye (--engine-triangles overrides)");
  t.number("host.texels_per_s", [](auto& c) -> auto& { return c.host.texels_per_s; }, 1.0, 1e15, "texels/s",
           "its fill rate: texels passing the depth test (--engine-fill overrides)");
  t.number("host.object_setup_s", [](auto& c) -> auto& { return c.host.object_setup_s; }, 0.0, 1.0, "s",
           "its set-up time per object drawn: state changes, transforms (--engine-setup overrides)");
  // plan: what `arpsim plan` records (sim/Planner)
  t.number("plan.scene_hash", [](auto& c) -> auto& { return c.plan.scene_hash; }, 0, INT64_MAX, "",
           "hash of the scene this configuration was planned for (0: not planned); a run with another scene warns once");
  t.number("plan.motion_hash", [](auto& c) -> auto& { return c.plan.motion_hash; }, 0, INT64_MAX, "",
           "hash of the motion this configuration was planned for: the walk (points and speed) and the head's own "
           "motion on it, if any (--motion, --trace) (0: not planned); a run with another, or with a scene and no walk, "
           "warns once");
  t.number("plan.ipd_m", [](auto& c) -> auto& { return c.plan.ipd_m; }, 0.0, 1.0, "m",
           "the distance between the eyes this configuration was planned for (--ipd): its tiles and faces were bounded "
           "for eyes that far apart; a planned run, or still frame, of the scene with another --ipd warns once "
           "(plan.scene_hash not 0, two eyes)");
  return t;
}

}  // namespace

const ParameterTable<ArpConfig>& arp_parameters() {
  static const ParameterTable<ArpConfig> t = make_parameters();
  return t;
}

namespace {
struct Checker {
  std::vector<ConfigIssue>& out;
  void fail(const std::string& key, std::string reason) { out.push_back({key, std::move(reason)}); }
};
}  // namespace

std::string MemoryConfig::absent_face_names() const {
  std::string s;
  for (int f = 0; f < 6; ++f)
    if (!faces[static_cast<size_t>(f)]) s += (s.empty() ? "" : ", ") + std::string(face_name(f));
  return s.empty() ? "none" : s;
}

namespace {
std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
// A memory index in decimal digits only, below `memories`.
bool memory_index(const std::string& s, int memories, int& out, std::string& why) {
  if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) {
    why = "\"" + quoted(s) + "\" is not a memory number";
    return false;
  }
  out = std::stoi(s);
  if (out >= memories) {
    why = "memory " + s + " is past memory.count (" + std::to_string(memories) + " memories, 0 .. " +
          std::to_string(memories - 1) + ")";
    return false;
  }
  return true;
}
}  // namespace

std::string ObjectAssignment::text() const {
  return name + ": " + (fastest == slowest ? std::to_string(fastest) : std::to_string(fastest) + "-" + std::to_string(slowest));
}

bool ObjectAssignment::parse(const std::string& text, int memories, ObjectAssignment& out, std::string& why) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) {
    why = "has no colon: expected \"name: m\" or \"name: a-b\"";
    return false;
  }
  ObjectAssignment a;
  a.name = trimmed(text.substr(0, colon));
  if (a.name.empty()) {
    why = "names no object before its colon";
    return false;
  }
  const std::string range = trimmed(text.substr(colon + 1));
  const size_t dash = range.find('-');
  if (dash == 0) {
    why = "\"" + quoted(range) + "\" is not a memory number (nor a range a-b of them)";
    return false;
  }
  if (!memory_index(trimmed(range.substr(0, dash)), memories, a.fastest, why)) return false;
  a.slowest = a.fastest;
  if (dash != std::string::npos && !memory_index(trimmed(range.substr(dash + 1)), memories, a.slowest, why)) return false;
  if (a.slowest < a.fastest) {
    why = "runs from memory " + std::to_string(a.fastest) + " to the faster memory " + std::to_string(a.slowest) +
          ": write the faster (lower) memory first";
    return false;
  }
  out = std::move(a);
  return true;
}

bool object_assignments(const MemoryConfig& m, std::vector<ObjectAssignment>& out, std::string& why) {
  out.clear();
  std::map<std::string, size_t> seen;  // name -> its string
  for (size_t i = 0; i < m.assignment.size(); ++i) {
    ObjectAssignment a;
    if (!ObjectAssignment::parse(m.assignment[i], m.count, a, why)) {
      why = "string " + std::to_string(i) + " (\"" + m.assignment[i] + "\") " + why;
      return false;
    }
    if (const auto [at, fresh] = seen.emplace(a.name, i); !fresh) {
      why = "strings " + std::to_string(at->second) + " and " + std::to_string(i) + " both name \"" + a.name + "\"";
      return false;
    }
    out.push_back(std::move(a));
  }
  return true;
}

std::vector<ConfigIssue> validate(const ArpConfig& c) {
  // Every declared range first, then what ties keys together.
  std::vector<ConfigIssue> issues = arp_parameters().check_ranges(c);
  Checker ck{issues};
  const auto& t = c.timing;
  if (t.fields_per_frame == 2 && issues.empty()) {
    const int64_t frame = int64_t{t.h_total()} * t.v_total();
    const int64_t lines = (t.v_active + 1) / 2;
    if (frame % 2 != 0)
      ck.fail("display.v_front_porch", "interlaced timing needs an even number of pixel clocks per frame");
    else if (lines * t.h_total() > frame / 2)
      ck.fail("display.v_active", "the active lines of one field do not fit in half a frame");
  }

  if (c.memory.faces_present() == 0) ck.fail("memory.faces", "leaves out every face: a memory with no storage (keep one at least)");
  if (issues.empty() && !c.memory.tiles.empty()) {
    std::vector<TileMap> maps;
    std::string why;
    if (!tile_maps(c.memory, maps, why))
      ck.fail("memory.tiles", why);
    else
      for (size_t m = 0; m < maps.size(); ++m)
        for (int f = 0; f < 6; ++f)
          if (c.memory.faces[static_cast<size_t>(f)] == 0 && maps[m].tiles(f) > 0)
            ck.fail("memory.tiles", "memory " + std::to_string(m) + " holds tiles on face " + std::string(face_name(f)) +
                                        ", which memory.faces leaves out (\"-\" there)");
  }
  if (!c.memory.tile_pool.empty() && static_cast<int>(c.memory.tile_pool.size()) != c.memory.count)
    ck.fail("memory.tile_pool", "has " + std::to_string(c.memory.tile_pool.size()) + " numbers and memory.count is " +
                                    std::to_string(c.memory.count) + ": one for each memory, or none (no pool)");
  if (issues.empty() && static_cast<int>(c.memory.tile_pool.size()) == c.memory.count) {
    // A pool holds tiles of the memory's two buffers: more slots than both could ever use describe memory
    // that is never there (and a hardware figure of it).
    std::vector<TileMap> maps;
    std::string why;
    const bool listed = !c.memory.tiles.empty() && tile_maps(c.memory, maps, why);
    const TileMap whole(c.memory.face_size, true);
    for (int m = 0; m < c.memory.count; ++m) {
      int64_t held = 0;
      for (int f = 0; f < 6; ++f)
        if (c.memory.faces[static_cast<size_t>(f)] != 0) held += (listed ? maps[static_cast<size_t>(m)] : whole).tiles(f);
      if (c.memory.tile_pool[static_cast<size_t>(m)] > 2 * held) {
        ck.fail("memory.tile_pool", "memory " + std::to_string(m) + "'s pool of " + std::to_string(c.memory.tile_pool[static_cast<size_t>(m)]) +
                                        " slots is more than its two buffers can use: " + std::to_string(held) +
                                        " tiles each (its faces present at face size " + std::to_string(c.memory.face_size) +
                                        (listed ? ", as memory.tiles lists them" : "") + "), at most " + std::to_string(2 * held));
        break;
      }
    }
  }
  if (issues.empty() && !c.memory.assignment.empty()) {
    std::vector<ObjectAssignment> a;
    std::string why;
    if (!object_assignments(c.memory, a, why)) ck.fail("memory.assignment", why);
  }
  const auto& l = c.lens;
  if (std::abs(l.center_offset_px) >= t.h_active / 2.0)
    ck.fail("lens.center_offset_px", "must be less than half of display.h_active in magnitude");
  if (issues.empty()) {
    // The distortion scale must stay positive over the whole panel, or the
    // table would fold the image over itself.
    const double hw = t.h_active / 2.0 + std::abs(l.center_offset_px);
    const double rmax = std::hypot(hw, t.v_active / 2.0) / (t.h_active / 2.0);
    for (int i = 0; i <= 1000; ++i) {
      const double r = rmax * i / 1000.0, r2 = r * r;
      const double s = l.k[0] + r2 * (l.k[1] + r2 * (l.k[2] + r2 * l.k[3]));
      if (!(s > 0.0)) {
        ck.fail("lens.k", "distortion scale k0+k1 r^2+k2 r^4+k3 r^6 is not positive at r=" + std::to_string(r));
        break;
      }
    }
  }

  if (c.memory.color_bits() > 32) ck.fail("memory.red_bits", "red+green+blue bits must not exceed 32");
  if (issues.empty()) {
    // The slowest memory's period, without overflow: each factor is at most 64 and checked as it grows.
    int64_t f = c.memory.update_frames;
    for (int m = 1; m < c.memory.count && f <= MemoryConfig::kMaxUpdateFrames; ++m) f *= c.memory.update_ratio;
    if (f > MemoryConfig::kMaxUpdateFrames)
      ck.fail("memory.update_ratio", "memory " + std::to_string(c.memory.count - 1) + " would be updated every memory.update_frames (" +
                                         std::to_string(c.memory.update_frames) + ") x update_ratio (" +
                                         std::to_string(c.memory.update_ratio) + ")^" + std::to_string(c.memory.count - 1) +
                                         " frames: more than " + std::to_string(MemoryConfig::kMaxUpdateFrames));
  }
  if (c.pipeline.aa == AaMode::Bilinear && c.widths.texel_frac < 1)
    ck.fail("datapath.texel_frac", "bilinear anti-aliasing needs at least 1 sub-texel bit");
  return issues;
}

std::vector<ConfigIssue> validate_timed(const ArpConfig& c) {
  std::vector<ConfigIssue> issues = validate(c);
  if (!issues.empty()) return issues;
  Checker ck{issues};
  const auto& tm = c.timed;
  const double period_ps = 1e12 / static_cast<double>(c.timing.pixel_clock_hz);
  for (int s = 0; s < kStageCount; ++s) {
    const auto& st = tm.stage[static_cast<size_t>(s)];
    const double per_register = static_cast<double>(st.logic_delay_ps) / st.latency_cycles;
    if (per_register > period_ps) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "%.0f ps of logic over %d register stage(s) needs %.0f ps per stage, more than the %.0f ps "
                    "pixel clock period (display.pixel_clock_hz %lld): add register stages or slow the clock",
                    static_cast<double>(st.logic_delay_ps), st.latency_cycles, per_register, period_ps,
                    static_cast<long long>(c.timing.pixel_clock_hz));
      ck.fail(std::string("timed.") + stage_key(static_cast<Stage>(s)) + "_latency", buf);
    }
  }
  if (c.memory.count > kCompositionInputs)
    ck.fail("memory.count", "is " + std::to_string(c.memory.count) + ", the timed models' composition unit compares at most " +
                                std::to_string(kCompositionInputs) + " memories");
  if (tm.fifo_depth < tm.min_fifo_depth())
    ck.fail("timed.fifo_depth", "is " + std::to_string(tm.fifo_depth) + ", must be at least the issue slack plus two (" +
                                    std::to_string(tm.min_fifo_depth()) + ") or the scan-out FIFO backs up");
  const PipelineSchedule sched(c);
  if (sched.issue_lead() >= sched.vblank_cycles())
    ck.fail("timed.issue_slack_cycles",
            "the pipeline issues pixels " + std::to_string(sched.issue_lead()) +
                " cycles ahead, not less than the vertical blanking (" + std::to_string(sched.vblank_cycles()) +
                " cycles): the next frame would be fetched before the buffers swap");
  if (sched.issue_lead() > c.timing.h_total() * int64_t{c.timing.v_active})
    ck.fail("timed.issue_slack_cycles", "the pipeline is deeper than the active picture");
  return issues;
}

}  // namespace arp::dp
