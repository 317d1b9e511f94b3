// `arpsim plan`: a configuration sized for one scene and its motion, each
// choice with its reason and the figures it came from (docs/planning.md):
// - the face size, from the angle between neighbouring display pixels after
//   the lens (the largest texel, at a face's centre, no coarser than the finest
//   pixel; any finer is not resolved);
// - the datapath's narrowest widths that keep the accuracy harness's texel
//   error within the bound, at that face size;
// - the display memories and their update periods (Regan & Pose's priority
//   classes): each object's validity period over the motion at theta_t, put
//   through the run's own priority rule (host::PriorityScheduler) for every
//   candidate ladder, the host's rendering load measured for each;
// - the cube faces any object reaches over the motion;
// - the depth code: a written flag for one memory, the narrowest that composes
//   several within a bound, measured (CompositionDepth).
// What it does not decide yet is listed in the plan itself (Plan::not_decided).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "CompositionDepth.hpp"
#include "HardwareCost.hpp"
#include "HeadMotion.hpp"
#include "RunSpec.hpp"
#include "host/cubemap/CubeMapImages.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"

namespace arp::sim {

// The most points of the motion a plan evaluates (evenly spread over it): also the most --fill-points.
inline constexpr int kMaxSamples = 4000;

struct PlanRequest {
  dp::ArpConfig base;                  // what the plan starts from: the defaults, --config, --set
  std::string base_source = "the embedded default";
  MemoryContents memories;             // the scene (.scene is required)
  std::string walk;                    // "gallery" or a walk file (required; --speed 0: standing at its first point)
  std::optional<double> walk_speed;    // as run --speed
  // The head's motion of its own, on top of facing where the walk goes (--motion, --trace; as a run turns the head):
  // the turning the priority rule sees. Standing (--speed 0), the motion planned over is its span (standing_span_s).
  HeadMotion head;
  double texel_error = 0;              // texels, max over the harness's samples (0: what `base` measures)
  std::optional<double> threshold_deg;  // theta_t (0: one texel at the planned face size; unset: base's memory.threshold_deg)
  std::string resolve = "centre";      // the display pixel a texel is held to: at the lens "centre", or the "finest"
  double load_tolerance = 0.10;        // a memory more must save more than this share of the host's load
  // Points of the motion where each object's fill is measured by rendering the whole scene (--fill-points); the
  // samples between interpolate the two around them. More follow the fill's peaks (a doorway, a wall close by) that
  // the engine's replay needs, at a render each.
  int fill_points = 16;
  // The most hardware display memory a ladder may take, MiB (whole faces present, both buffers, every eye;
  // unset: what the starting configuration takes; 0: no limit).
  std::optional<double> memory_limit_mib;
  bool size_widths = true;             // false: keep the starting configuration's datapath widths (--keep-widths)
  // The share of composed texels (two or more memories hold a surface) the depth code may compose from the
  // wrong memory, with several memories (unset: what the starting configuration's width measures).
  std::optional<double> depth_error;
  // false (--whole-faces): every tile of the faces present (no memory.tiles), a display memory without a
  // tile table; true: the tiles the motion can draw on where that takes less memory than whole faces.
  bool tile_sparse = true;
  // false (--fixed-tiles): each memory keeps the fixed tiles above and no tile pool; true: a memory takes a tile
  // pool (memory.tile_pool) where that takes less than its tiles or whole faces.
  bool tile_pool = true;
  // true (--weigh-pools): a ladder is held to the memory limit with the tile pools it would take (with tile_pool);
  // false: with its fixed tiles (a pool, taken after, only lowers the memory).
  bool weigh_pools = false;
  // false (--objects-only): keep object-level priority without weighing region priority rendering.
  bool weigh_regions = true;
  // true (--take-regions): take region priority rendering where the weighing finds it keeps objects within theta_t
  // as well and renders less; by default it is weighed and reported only (its tearing between regions is not
  // bounded by the plan: docs/planning.md).
  bool take_regions = false;
  // Progress: step `step` (1 .. steps) of the plan's, `fraction` of it done, what it does (ProgressLine::update_step).
  // A step the plan does not need is not reported (the number jumps).
  std::function<void(int step, int steps, double fraction, const std::string& what)> progress;
};

struct PlanChoice {
  std::string keys;    // the configuration keys it sets
  std::string value;   // as written in the configuration
  std::string reason;  // why, with the figures
};

// One candidate ladder of display memories and what the motion costs with it.
struct LadderLoad {
  int count = 1, update_frames = 1, update_ratio = 2;
  double triangles_per_s = 0;     // host rendering load, mean over the motion
  double texels_per_s = 0;        // texels the host fills (passing the depth test), both eyes, mean over the motion
  // The share of each second the rendering engine (host.*) is busy, mean over the motion: every object drawn
  // for each eye at each update of its memory, its set-up, its triangles sent to every face its bound
  // reaches from both eyes (one at least), and its fill as measured by rendering (interpolated between the
  // points rendered). Above 1, the engine cannot carry the ladder.
  double engine_busy = 0;
  double late_share = 0;          // object-samples whose memory updates slower than their validity needs
  int64_t skipped = 0;            // updates the configured engine skips over the motion, replayed (EngineNeed)
  std::vector<double> objects;    // mean objects in each memory
  // Its hardware display memory at the planned face size and faces, with the depth code it is weighed at: as
  // whole faces, and as it would be planned -- each memory holding only the tiles its objects can be drawn on
  // over the motion where that takes less, or with --weigh-pools a tile pool where that takes less still (0: not
  // bounded, where whole faces are within the memory limit or the plan keeps whole faces). The memory limit holds
  // the less of the two.
  int64_t memory_bytes_whole = 0, memory_bytes_tiled = 0;
  int64_t memory_bytes_weighed() const {
    return memory_bytes_tiled > 0 ? std::min(memory_bytes_whole, memory_bytes_tiled) : memory_bytes_whole;
  }
};

// The rendering engine a ladder needs (engine_need): the run's engine replayed at every display frame of the motion
// (HostSimulation::before_frame: the memories due rendered one after another, fastest first, each new image
// swapped in at the first vertical blank after it is done, a memory due again before then skipped), each object
// moving as a run moves it (only between memories rendering in the same frame, as far toward where the rule puts it
// as those allow, and memories exchanging objects swapping together at the last of them to finish), each render
// costing what ladder_load charges (set-up, triangles, interpolated fill, for each eye), the fill measured with each
// memory's objects rendered on their own, as its render draws them. `scale` is the least multiple of the configured engine's rates (its
// triangle and fill rates times it, its set-up time over it) at which no render is skipped, found by
// bisection to 1e-6 (no skip is monotone in it: a faster engine finishes every render no later); 0 where no
// render can be skipped (no memory due twice within the motion; any engine carries it).
// An estimate, for what it leaves out of a run: the fill between rendered points (interpolated) and from each eye's
// own point (measured from the walk's), the tile and pool
// guards that send an object to a faster memory, a plan's memory.assignment, and, over a motion sampled every few
// frames, the frames between samples (each takes the sample before it).
struct EngineNeed {
  double scale = 0;
  int64_t renders = 0;          // at the configured engine
  int64_t skipped = 0;          // at the configured engine: a memory due while its last image is not yet shown
  double longest_render_s = 0;  // one memory's render at the configured engine, both eyes
  double fill_texels_per_s = 0; // scale x the engine's fill rate: what the needed engine writes into display memory
};

// Region priority rendering (Chow, Pose & Regan 2005) with the planned memories, weighed against object-level:
// the run's own region rule (host::RegionScheduler, host::segment_scene) stepped at every display frame of the
// motion, each memory's pieces rendered at each update it asks for.
struct RegionLoad {
  double size_m = 0, margin_m = 0;
  double triangles_per_s = 0;     // mean over the motion
  // For one eye: pieces drawn and triangles sent (once for each face a piece's bound reaches) a second.
  double pieces_per_s = 0, triangles_sent_per_s = 0;
  double engine_busy = 0;         // set-up, triangles and fill of the pieces, for each eye (each piece's fill its object's by triangles)
  // Piece-frames whose memory updates slower than the piece's validity at theta_t needs (LadderLoad::late_share's
  // measure): memory m updates every time the user moves its threshold distance, at most once a frame.
  double late_share = 0;
  int64_t segments = 0, reassignments = 0;
  std::string refused;            // why this size cannot be used here ("" : weighed)
};

// The tiles of each planned memory that any of its objects can be drawn on over the motion (a bound for an
// eye within half the distance between the eyes (--ipd) of the walk's point, at the motion's samples).
struct TileBound {
  int tiles_per_row = 0;
  // Per memory: the tiles reachable (none on a face the plan leaves out); the plan's memory.tiles when
  // they take less memory than whole faces.
  std::vector<dp::TileMap> maps;
  std::vector<int64_t> per_memory;  // tiles of one eye's bank of each memory (each eye's is bounded alike)
  // A tile pool instead (memory.tile_pool), per memory: the most tiles its objects can be drawn
  // on at one sample of the motion (one image's: `at_once`), and at one sample and the most of one to two update
  // periods before together (the image being drawn and the one shown: `pooled`, the slots a pool both buffers
  // share needs).
  std::vector<int64_t> at_once, pooled;
  bool reachable(int memory, int face, int tx, int ty) const { return maps[static_cast<size_t>(memory)].has(face, tx, ty); }
};

struct Plan {
  dp::ArpConfig config;
  std::vector<PlanChoice> choices;
  std::vector<std::string> not_decided;  // what a plan should decide and this one does not (yet)
  std::vector<std::string> warnings;     // what the user should know about the inputs (a trace that starts late)
  std::string scene_name;
  int64_t scene_hash = 0;
  size_t objects = 0, triangles = 0;
  double motion_s = 0;                    // the motion's span planned over
  int samples = 0;                        // points of the motion evaluated
  int fill_points = 0;                    // of them, rendered to measure each object's fill
  // Face size
  double pixel_angle_min_rad = 0, pixel_angle_centre_rad = 0;
  // Widths
  double texel_error_bound = 0, texel_error_base = 0, texel_error_planned = 0;
  int harness_runs = 0;
  // Memories
  double threshold_rad = 0;
  LadderLoad planned, base_ladder, best;  // best: the lowest load of any candidate
  EngineNeed planned_need, base_need;     // the engine each of the two ladders needs
  std::vector<LadderLoad> ladders;        // every candidate weighed
  double fastest_need_frames = 0;        // the shortest validity of any object, in display frames
  std::array<bool, 6> faces_reached{};    // by some object at some point of the motion
  // Depth code (several memories): the planned ladder's composition at every width, and the bound used
  CompositionDepth composition;
  double depth_error_bound = 0;
  // Display memory as hardware: the planned configuration's (display_memory_bytes: tile-sparse where it
  // lists tiles), the same memories as whole faces (eyes x memories x 2 buffers x faces present x S^2 x
  // texel bits), and the starting configuration's as whole faces
  int64_t memory_bytes_planned = 0, memory_bytes_whole = 0, memory_bytes_base = 0;
  int64_t memory_limit_bytes = 0;         // the limit a ladder was held to (0: none)
  int ladders_over_limit = 0;             // ladders the engine could carry, left out for their memory
  // The tiles drawn on (a tile-sparse display memory's storage and tile tables, every eye)
  TileBound tiles;
  int64_t memory_bytes_tiled = 0;
  // The same memories each bank with a tile pool of tiles.pooled slots where that takes less than its tiles or
  // whole faces (bank_bits_pooled), every eye -- what the plan takes unless --fixed-tiles -- and each memory with
  // its fixed tiles where those take less than whole faces, no pool (memory.tiles alone).
  int64_t memory_bytes_pooled = 0, memory_bytes_fixed_tiles = 0;
  // Each object's memories over the motion at the planned ladder (memory.assignment's entries; none with one memory).
  std::vector<dp::ObjectAssignment> assignment;
  // Region priority rendering weighed at each size (none with --objects-only, or standing); the one taken is
  // config.memory.region_size_m (0: objects).
  std::vector<RegionLoad> regions;
};

// InputError for a bad request (no scene, a bound no widths meet -- naming the best achievable).
Plan make_plan(const PlanRequest& r);

// The configuration file (every key; every command accepts it as --config).
std::string plan_config_text(const Plan& p);
// The human-readable account: each choice with its reason, the figures, what is not decided.
std::string plan_markdown(const Plan& p, const PlanRequest& r);
// The tile bound as a picture (`plan` writes it beside plan.md): a row for each memory, fastest at the top,
// of its six faces +X -X +Y -Y +Z -Z left to right, kTilePixels a tile and kTilePixels between faces and rows,
// each face as the display memory stores it (texel row 0 at the top). A tile the memory can be drawn on is
// light, one it cannot dark grey, a face the plan leaves out dark red.
constexpr int kTilePixels = 4;
host::RgbImage plan_tiles_image(const Plan& p);

}  // namespace arp::sim
