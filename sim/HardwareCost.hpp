// What a datapath configuration costs in hardware, for the trade table:
// synthesized figures where the RTL was synthesized with exactly this
// configuration's parameters (docs/hdl-cost.csv, written by
// scripts/hdl-cost.sh; embedded at build time, an input to the table, not
// measured by it), and otherwise -- always beside it -- a bit-count model of
// the per-pixel arithmetic, stated as a model: multiplier bits (a x b for an
// a-bit by b-bit product), adder bits and table bits. The model ranks widths;
// it is no cell count.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"

namespace arp::sim {

struct SynthesizedModule {
  std::string configuration, module;   // the cost CSV's names: "default", "omu"
  int64_t cells = 0, flip_flops = 0, logic_depth = 0, ice40_lut4 = 0;
};

struct BitCountModel {
  int64_t multiplier_bits = 0, adder_bits = 0, table_bits = 0;
};

struct HardwareCost {
  // One per RTL module whose synthesized parameters equal this configuration's;
  // all four (omu, cfag, comp, filt) or none is the usual case.
  std::vector<SynthesizedModule> synthesized;
  BitCountModel model;
  bool fully_synthesized() const;  // every RTL module matched
  int64_t cells() const;           // sums over the matched modules
  int64_t lut4() const;
  int64_t logic_depth() const;     // the deepest matched module
  std::string configuration() const;  // the cost CSV's name of the matched configuration, "" if none
};

HardwareCost hardware_cost(const dp::ArpConfig& c);

// The cost CSV's provenance line for tables ("scripts/hdl-cost.sh, yosys 0.23 ..."): its rows and configurations.
std::string hardware_cost_source();

// The hardware's display memory in bytes for a configuration: eyes x memories x two buffers (front
// and back) x the faces present (memory.faces) x S^2 texels of colour + depth bits -- where memory.tiles
// leaves out a tile of a face present in a memory, that memory as a tile-sparse one holding the tiles it
// lists (as display_memory_bytes_tiled), and where memory.tile_pool gives a memory a pool, a bank of that
// many slots (bank_bits_pooled) -- the total then rounded up to whole bytes.
int64_t display_memory_bytes(const dp::ArpConfig& c);
// The tiles one memory's bank holds under memory.tiles on the faces present, or -1 when it holds every tile of
// them (whole faces, no tile table). The configuration must be valid.
int64_t tiles_held(const dp::ArpConfig& c, int memory);
// The same display memories holding only some 32 x 32 tiles (`tiles`: how many, bank by bank): both buffers
// of those tiles, every one a whole tile slot (a face's last row and column of tiles are partial when S is
// not a multiple of 32, but a tile table addresses equal slots), and per bank one tile table for both
// buffers (an entry per tile of each face present, wide enough to number the bank's tiles and "absent") --
// what a tile-sparse memory holding them needs. Bytes, rounded up.
int64_t display_memory_bytes_tiled(const dp::ArpConfig& c, const std::vector<int64_t>& tiles);
// The tiles it drew on (tiles_ever_written).
int64_t display_memory_bytes_tiled(const dp::ArpConfig& c, const dp::DisplayMemorySet& m);
// One bank (an eye's, of one memory), bits: whole faces (both buffers of the faces present), or holding `tiles`
// tiles (as display_memory_bytes_tiled); and whether the tiles take less.
int64_t bank_bits_whole(const dp::ArpConfig& c);
int64_t bank_bits_tiled(const dp::ArpConfig& c, int64_t tiles);
bool tiles_take_less(const dp::ArpConfig& c, int64_t tiles);
// One bank with a tile pool instead (memory.tile_pool, dp::DisplayMemoryBank's pool): `slots` 32 x 32 tile slots shared by
// the two buffers, each buffer's tiles allocated from them as it is drawn and freed when it is drawn again, and
// a tile table per buffer (an entry per tile of each face present, wide enough to number the slots and
// "absent"). Bits.
int64_t bank_bits_pooled(const dp::ArpConfig& c, int64_t slots);
// Every bank of `m` with a pool of the slots it needed at once in a run (tiles_most_at_once). Bytes, rounded up.
int64_t display_memory_bytes_pooled(const dp::ArpConfig& c, const dp::DisplayMemorySet& m);

// The most memory the model can take for a configuration: every display memory's tiles written (eyes x
// memories x 2 buffers x faces present x tiles of 33 x 33 64-bit words), the host renderer's float faces
// and words when a scene is drawn (six faces x S^2 x 44 bytes and two S^2 tables of doubles), and with
// truth_face_size >= 0 the truth's memory and render (0: at the run's face size), and the display's frames (48
// bytes a display pixel, measured). InputError naming memory.face_size (in config_source), --truth-face-size or,
// where the display's frames are the largest part, display.h_active, when that is more than the machine has
// available (available_memory_bytes: MemAvailable, or a smaller address-space limit): a face size within the key's range can ask for hundreds of GB, and the
// allocations fail inside parallel regions, where nothing can catch them. Nothing when MemAvailable is unknown.
void check_model_fits_memory(const dp::ArpConfig& c, const std::string& config_source, bool draws_scene, int truth_face_size = -1);
// Throws InputError(place, key, ...) when the planner's renders at `face_size` (the renderer's faces and one
// display memory's banks for `eyes`, as its depth-code measurement holds) would take more than is available.
// `why`: where the face size comes from.
void check_plan_fits_memory(int face_size, int eyes, const std::string& place, const std::string& key, const std::string& why);

// For tests: the RTL modules the cost CSV must cover, and the parsed rows.
std::vector<std::string> rtl_module_keys();
std::vector<SynthesizedModule> synthesized_rows();

}  // namespace arp::sim
