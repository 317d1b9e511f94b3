// Every parameter of the pixel path, with the defaults of brief §3. Plain data
// structs (hot paths read plain fields); each field is declared once more, as a
// row of arp_parameters() with its key, range, unit and doc, from which JSON
// read and write, --set, range checks and docs/configuration.md are produced.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "FixedPoint.hpp"
#include "common/Parameter.hpp"

namespace arp::dp {

enum class EyeScan : uint8_t { Lockstep, SideBySide };
enum class LatchPolicy : uint8_t { PerFrame, PerField, PerScanline, PerPixel };
enum class DividerKind : uint8_t { ReciprocalLut, Exact };
enum class AaMode : uint8_t { Off, Bilinear };

// The words each enum's values are written as (configuration, reports, options).
const EnumNames<EyeScan>& eye_scan_names();          // lockstep, side_by_side
const EnumNames<LatchPolicy>& latch_policy_names();  // frame, field, scanline, pixel
const EnumNames<DividerKind>& divider_names();       // lut, exact
const EnumNames<AaMode>& aa_names();                 // off, bilinear
inline std::string to_string(EyeScan v) { return enum_name(eye_scan_names(), v); }
inline std::string to_string(LatchPolicy v) { return enum_name(latch_policy_names(), v); }
inline std::string to_string(DividerKind v) { return enum_name(divider_names(), v); }
inline std::string to_string(AaMode v) { return enum_name(aa_names(), v); }
inline bool parse(const std::string& s, EyeScan& out) { return enum_parse(eye_scan_names(), s, out); }
inline bool parse(const std::string& s, LatchPolicy& out) { return enum_parse(latch_policy_names(), s, out); }
inline bool parse(const std::string& s, DividerKind& out) { return enum_parse(divider_names(), s, out); }
inline bool parse(const std::string& s, AaMode& out) { return enum_parse(aa_names(), s, out); }

struct VideoTimingConfig {
  int eyes = 2;                   // 2 = stereo, 1 = mono
  EyeScan eye_scan = EyeScan::Lockstep;
  int h_active = 640, h_front_porch = 16, h_sync = 96, h_back_porch = 48;
  int v_active = 480, v_front_porch = 10, v_sync = 2, v_back_porch = 33;
  int64_t pixel_clock_hz = 25'175'000;
  int fields_per_frame = 1;       // 1 progressive, 2 interlaced (odd lines in field 1)
  int h_total() const { return (eye_scan == EyeScan::SideBySide ? eyes : 1) * h_active + h_front_porch + h_sync + h_back_porch; }
  // A mode from its numbers: active, front porch, sync, back porch for each direction, and the clock.
  static VideoTimingConfig mode(int eyes, std::array<int, 4> h, std::array<int, 4> v, int64_t pixel_clock_hz) {
    VideoTimingConfig c;
    c.eyes = eyes;
    c.h_active = h[0], c.h_front_porch = h[1], c.h_sync = h[2], c.h_back_porch = h[3];
    c.v_active = v[0], c.v_front_porch = v[1], c.v_sync = v[2], c.v_back_porch = v[3];
    c.pixel_clock_hz = pixel_clock_hz;
    return c;
  }
  int v_total() const { return v_active + v_front_porch + v_sync + v_back_porch; }
};

struct LensConfig {
  double fov_deg = 90.0;                  // horizontal field of view per eye (undistorted)
  std::array<double, 4> k{1.0, 0.0, 0.0, 0.0};  // scale(r) = k0 + k1 r^2 + k2 r^4 + k3 r^6
  double center_offset_px = 0.0;          // lens centre moved toward the nose, pixels
};

struct DatapathWidths {
  int vec_frac = 14;                      // lens vectors, signed Q1.vec_frac
  int mat_frac = 14;                      // orientation matrix, signed Q1.mat_frac
  int rot_frac = 14;                      // rotated vector, signed Q1.rot_frac
  Rounding rot_rounding = Rounding::HalfUp;
  DividerKind divider = DividerKind::ReciprocalLut;
  int recip_index_bits = 8;               // LUT has 2^index_bits entries
  int recip_frac_bits = 16;               // LUT entries and refined reciprocal, Q0.recip_frac
  int newton_steps = 1;                   // Newton-Raphson refinements after the LUT
  int quot_frac = 16;                     // sc/|ma|, signed Q1.quot_frac
  Rounding div_rounding = Rounding::HalfUp;
  int texel_frac = 8;                     // sub-texel position bits (bilinear weights)
  Rounding texel_rounding = Rounding::Floor;
};

// Frames between host updates of memory m when memory 0 updates every `first` frames and each next
// one `ratio` times less often (Regan & Pose's priority rendering; memory.update_*).
inline int64_t update_period_frames(int64_t first, int64_t ratio, int m) {
  int64_t f = first;
  for (int i = 0; i < m; ++i) f *= ratio;
  return f;
}

struct MemoryConfig {
  int count = 4;                          // display memories per eye
  int face_size = 512;                    // S: each face is S x S texels
  int red_bits = 8, green_bits = 8, blue_bits = 8;
  int depth_bits = 16;                    // code 2^depth_bits-1 is reserved for "empty"
  std::array<int, 3> background{0, 0, 0};  // RGB8 shown where every memory is empty
  // The cube faces each memory has, +X -X +Y -Y +Z -Z (1: present; 0: absent -- no storage, reads
  // empty, the host's writes to it are lost and counted). `arpsim plan` leaves out the faces no object
  // of the scene reaches over the motion.
  std::array<int, 6> faces{1, 1, 1, 1, 1, 1};
  // The 32 x 32 tiles each memory holds (dp::TileMap's text, one string per memory; none: every tile of every
  // face present). `arpsim plan` writes the tiles its scene's motion can draw on.
  std::vector<std::string> tiles{};
  // A tile pool per memory (one number per memory; none: no pool anywhere): that many 32 x 32 tile slots,
  // shared by the memory's two buffers, each buffer's tile table naming the slot of each of its tiles. A
  // tile whose own texels are first drawn while every slot is taken gets none until its buffer is cleared:
  // its texels are lost and counted. 0: that memory has no pool (its tiles or whole faces, both buffers).
  // `arpsim plan` sizes the pools from its scene's motion (docs/planning.md).
  std::vector<int64_t> tile_pool{};
  // Object-level priority rendering (Regan & Pose): memory m is updated every
  // update_frames x update_ratio^m display frames (1, 2, 4, 8 by default).
  int update_frames = 1;
  int update_ratio = 2;
  double threshold_deg = 0;  // theta_t: an object is re-rendered before its image moves this far (0: one texel)
  // The objects' memories, bounding the priority rule (ObjectAssignment's text, one string per object name; none:
  // the rule alone). `arpsim plan` writes the memories its rule gives each object over the motion.
  std::vector<std::string> assignment{};
  // Region priority rendering (Chow, Pose & Regan 2005) instead of object-level: the world cut into square
  // columns of region_size_m (0: object-level), re-assigned once the user is region_margin_m inside a new one.
  double region_size_m = 0;
  double region_margin_m = 0.5;
  int color_bits() const { return red_bits + green_bits + blue_bits; }
  int faces_present() const {
    int n = 0;
    for (const int f : faces) n += f;
    return n;
  }
  int64_t pool_slots(int m) const {  // 0: none (also past the list's end, in a configuration not validated)
    return static_cast<size_t>(m) < tile_pool.size() ? tile_pool[static_cast<size_t>(m)] : 0;
  }
  std::string absent_face_names() const;  // "+Y, -Y" ("none" when every face is present)
  // Frames between host updates of memory m (validate() keeps it within kMaxUpdateFrames).
  int64_t frames_per_update(int m) const { return update_period_frames(update_frames, update_ratio, m); }
  static constexpr int64_t kMaxUpdateFrames = int64_t{1} << 20;
};

// One string of memory.assignment: the objects named `name` (every object of the scene with that name) are kept
// in memories fastest .. slowest (memory 0 the fastest): the priority rule's choice for them is clamped to that
// range, before the storage guards (tiles, pools), which may still send one faster. Written "name: m" (fastest =
// slowest = m, pinned) or "name: a-b"; the name is everything before the last colon, spaces around it trimmed.
struct ObjectAssignment {
  std::string name;
  int fastest = 0, slowest = 0;
  std::string text() const;  // what parse() reads back as this entry
  // False, with why, where `text` is not such a string or names a memory past `memories`.
  static bool parse(const std::string& text, int memories, ObjectAssignment& out, std::string& why);
};
// memory.assignment's entries; false with why (naming the string) where one does not parse or a name repeats.
bool object_assignments(const MemoryConfig& m, std::vector<ObjectAssignment>& out, std::string& why);

// The host's simulated rendering engine (host::RenderEngine): how long a render
// takes, from what it drew -- never the wall-clock time of arpsim's own code, so
// runs are deterministic. The defaults are a modest engine that renders the
// whole default gallery, both eyes, at 60 Hz with a little headroom
// (docs/host.md), so the baseline is not overloaded.
struct HostEngineConfig {
  double triangles_per_s = 50e6;  // triangle set-up rate (per face a triangle is sent to)
  double texels_per_s = 1e9;      // fill rate (texels passing the depth test)
  double object_setup_s = 5e-6;   // per object drawn (state changes, transforms)
};

// The distance between the eyes when none is given (--ipd), in metres.
inline constexpr double kDefaultIpdM = 0.064;

// What `arpsim plan` records of the scene, the motion and the eyes it planned for.
struct PlanRecord {
  int64_t scene_hash = 0;   // host::scene_hash of the scene (0: not planned)
  int64_t motion_hash = 0;  // sim::motion_hash of the walk and the head motion on it (0: not planned)
  double ipd_m = kDefaultIpdM;  // the distance between the eyes it planned for (--ipd; plans from before it was kept: the default)
};

struct PipelineConfig {
  LatchPolicy latch = LatchPolicy::PerScanline;
  int latch_lead_cycles = 0;              // extra lead: the register is sampled this many pixel clocks before
                                          // the latch-point pixel enters the orientation matrix unit
  AaMode aa = AaMode::Bilinear;
  int display_bits = 8;                   // per channel at the HMD (<= 10: frames are packed in 32 bits)
  int64_t photon_delay_ps = 0;            // panel response after scan-out
};

// The timed models' pipeline stages, in data-flow order after the video
// timing generator's issue.
enum class Stage : uint8_t { Lens, Rotate, Address, Fetch, Compose, Filter, ScanOut };
constexpr int kStageCount = 7;
const char* stage_key(Stage s);  // "lens", "rotate", ... (configuration keys)

struct StageTiming {
  int latency_cycles = 1;      // pixel clocks from taking a pixel to it being visible to the next stage
  int64_t logic_delay_ps = 0;  // combinational delay of the stage's arithmetic, split over its register stages
};

// Hardware timing of the cycle models. Defaults are this project's
// assumptions (the papers give no stage timings), chosen so every stage's
// logic fits a 25.175 MHz clock; see docs/timed-models.md.
struct TimedConfig {
  std::array<StageTiming, kStageCount> stage{{{1, 8'000},     // lens vector ROM read
                                              {2, 24'000},    // three multiply-accumulate rows
                                              {4, 60'000},    // reciprocal LUT, Newton step, two multiplies
                                              {2, 40'000},    // display memory read (all memories in parallel)
                                              {1, 10'000},    // depth compare tree
                                              {2, 20'000},    // bilinear weights and blend
                                              {1, 8'000}}};   // colour rescale LUT to the panel
  int fifo_depth = 4;                     // tokens each inter-stage FIFO holds
  int issue_slack_cycles = 2;             // pixels are issued this much earlier than the stage latencies need
  int64_t host_clock_hz = 100'000'000;    // host -> display memory write port clock
  int host_texels_per_cycle = 1;          // texels the write port stores per host clock
  // The shallowest FIFO allowed: the scan-out FIFO holds slack + 1 pixels at the start of each clock and,
  // having no bypass, must have room for one more while it is read.
  int min_fifo_depth() const { return issue_slack_cycles + 2; }
};

constexpr int kCompositionInputs = 8;     // memories the timed models' composition unit can compare

struct ArpConfig {
  VideoTimingConfig timing;
  LensConfig lens;
  DatapathWidths widths;
  MemoryConfig memory;
  PipelineConfig pipeline;
  TimedConfig timed;
  HostEngineConfig host;
  PlanRecord plan;
};

using arp::ConfigIssue;

// Every parameter of ArpConfig, in sections display, lens, datapath, memory,
// pipeline, timed, host, plan: the one declaration of each key's range, unit and doc.
const ParameterTable<ArpConfig>& arp_parameters();

// Every constraint a configuration must meet so no stage can overflow its
// 64-bit arithmetic; an empty result means valid.
std::vector<ConfigIssue> validate(const ArpConfig& c);

// The further constraints of the timed models (hardware that must meet its
// clock, FIFOs that exist, a composition unit with enough inputs, a pipeline
// that drains inside vertical blanking); empty means the hardware can run it.
std::vector<ConfigIssue> validate_timed(const ArpConfig& c);

}  // namespace arp::dp
