// One display memory: 6 faces x S x S texels of colour + depth, double
// buffered. The host writes the back buffer and commits; the swap happens at
// vertical blank. Storage is sparse in 32x32 tiles: a face or tile never
// written costs no memory and reads as "empty" (depth code 2^depth_bits - 1).
// Each buffer keeps its tiles in one pool addressed by 32-bit tile numbers
// (tile 0 is the empty tile), so a texel is two plain indexed loads --
// pool[index[tile] * 1089 + word] -- which the functional model's passes
// can issue as vector gathers. A stored tile is 33 x 33 words: its 32 x 32
// texels plus an apron, a copy of the right neighbour's first column, the
// bottom neighbour's first row and the bottom-right neighbour's first texel,
// so the four taps of any bilinear quad lie in the tile of its top-left tap. Writes keep the aprons up to date.
// A texel is one 64-bit word: colour in the low 32 bits (R:G:B packed,
// red highest), depth in the high 32 bits.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "ArpConfig.hpp"
#include "TileMap.hpp"

namespace arp::dp {

struct MemoryFormat {
  int face_size = 512;
  int red_bits = 8, green_bits = 8, blue_bits = 8, depth_bits = 16;
  std::array<bool, 6> present{true, true, true, true, true, true};  // memory.faces
  MemoryFormat() = default;
  explicit MemoryFormat(const MemoryConfig& m)
      : face_size(m.face_size), red_bits(m.red_bits), green_bits(m.green_bits), blue_bits(m.blue_bits),
        depth_bits(m.depth_bits) {
    for (size_t f = 0; f < 6; ++f) present[f] = m.faces[f] != 0;
  }
  uint32_t empty_depth() const { return static_cast<uint32_t>((uint64_t{1} << depth_bits) - 1); }
  uint64_t empty_word() const { return uint64_t{empty_depth()} << 32; }
  int color_bits_total() const { return red_bits + green_bits + blue_bits; }
  uint32_t pack_color(uint32_t r, uint32_t g, uint32_t b) const {
    return (r << (green_bits + blue_bits)) | (g << blue_bits) | b;
  }
  // 8-bit channel -> channel code of the memory's width, rounded to nearest.
  uint32_t pack_rgb8(int r8, int g8, int b8) const;
};

// pack_rgb8 tabulated, for loops over many texels: each channel's code in place for every 8-bit value,
// a colour word the three ORed (pack_color's fields do not overlap). Values 0 .. 255.
class Rgb8Packer {
 public:
  explicit Rgb8Packer(const MemoryFormat& f) {
    for (int v = 0; v < 256; ++v) {
      r_[static_cast<size_t>(v)] = f.pack_rgb8(v, 0, 0);
      g_[static_cast<size_t>(v)] = f.pack_rgb8(0, v, 0);
      b_[static_cast<size_t>(v)] = f.pack_rgb8(0, 0, v);
    }
  }
  uint32_t operator()(uint8_t r8, uint8_t g8, uint8_t b8) const { return r_[r8] | g_[g8] | b_[b8]; }

 private:
  std::array<uint32_t, 256> r_{}, g_{}, b_{};
};

inline uint32_t texel_color(uint64_t w) { return static_cast<uint32_t>(w); }
inline uint32_t texel_depth(uint64_t w) { return static_cast<uint32_t>(w >> 32); }

class DisplayMemoryBank {
 public:
  static constexpr int kTileShift = 5;
  static constexpr int kTile = 1 << kTileShift;
  static constexpr int kTileStride = kTile + 1;                    // words a stored row: 32 texels + apron
  static constexpr int kTileWords = kTileStride * kTileStride;     // 1089 words a stored tile
  // Word of local texel (lx, ly), 0 <= lx, ly <= 32 (32: the apron).
  static constexpr int tile_word(int lx, int ly) { return ly * kTileStride + lx; }
  // Tiles a row (and column) of a face of S x S texels: the last may be partial.
  static constexpr int tiles_per_row_of(int face_size) { return (face_size + kTile - 1) / kTile; }

  // `tiles`: the tiles it holds (memory.tiles; default every tile). A texel drawn on a tile it does not hold is
  // lost and counted (writes_lost_off_tiles), and so are its copies in its neighbours' aprons: such a tile reads
  // empty, as in a tile-sparse memory without it. A tile not held may still be allocated here to carry the
  // apron of a held neighbour (the model's copy of that neighbour's edge, not storage of its own).
  // `pool_slots` > 0: a tile pool (memory.tile_pool) -- at most that many tiles, both buffers together, have
  // their own texels stored; a tile whose first own texel is drawn while every slot is taken gets none until its
  // buffer is cleared: its texels, and their copies in its neighbours' aprons, are lost and counted
  // (writes_lost_pool_full), and it reads empty, as a tile not held does. Which tiles miss out depends on the
  // order they are drawn in: write() texel by texel, write_face and reserve_faces face by face (+X .. -Z),
  // tiles row-major. 0: no pool.
  explicit DisplayMemoryBank(const MemoryFormat& f, TileMap tiles = {}, int64_t pool_slots = 0);
  DisplayMemoryBank(const DisplayMemoryBank&) = delete;
  DisplayMemoryBank& operator=(const DisplayMemoryBank&) = delete;

  const MemoryFormat& format() const { return fmt_; }

  // Host port (back buffer). Coordinates and codes are checked: out of range throws std::out_of_range.
  // A write to a face the format leaves out (memory.faces) is lost, as in hardware without that face,
  // and counted (writes_lost); one to a tile the bank does not hold (memory.tiles) likewise (writes_lost_off_tiles).
  void write(int face, int x, int y, uint32_t color, uint32_t depth);
  uint64_t read_back(int face, int x, int y) const { return fetch(back_, face, x, y); }
  // A whole face at once (S x S words, row-major): every word but those equal to `skip` written as write()
  // would, texel by texel -- the same tiles allocated, the same aprons -- a tile at a time. Returns the
  // words stored (0 on an absent face: its words are lost and counted); std::out_of_range as write() for a
  // bad face or a code wider than the format.
  int64_t write_face(int face, const uint64_t* words, uint64_t skip);
  // The same for several faces (null: a face not written), in two steps so that the copying can run on
  // several threads: reserve_faces() checks every face's words (throwing, as write_face, before anything
  // changes), counts what is lost to absent faces and allocates every tile the words touch, growing the
  // pool once by exactly what they need; then store_face() copies one face's words into its tiles, and
  // calls for distinct faces may run concurrently (each face's tiles are its own). Returns the words stored.
  int64_t reserve_faces(const std::array<const uint64_t*, 6>& words, uint64_t skip);
  // Precondition: reserve_faces() was given these words; then it cannot throw (callers run it inside
  // OpenMP regions). Misuse -- a word with no tile -- is a std::logic_error, after the tiles before it.
  void store_face(int face, const uint64_t* words, uint64_t skip);
  int64_t writes_lost() const { return lost_; }  // texels written to absent faces, ever
  int64_t writes_lost_off_tiles() const { return lost_tiles_; }  // texels written to tiles not held on faces present, ever
  int64_t writes_lost_pool_full() const { return lost_pool_; }  // texels written to held tiles the pool had no slot for, ever
  int64_t pool_slots() const { return pool_slots_; }            // 0: no pool
  const TileMap& tiles() const { return tiles_; }
  bool holds(int face, int tx, int ty) const { return !tile_sparse_ || tiles_.has(face, tx, ty); }
  bool holds_every_tile() const { return !tile_sparse_; }  // of every face present
  int64_t texels_written() const { return written_; }  // texels stored (write, write_face, reserve_faces), ever
  // The tiles whose own 32 x 32 texels (not the apron) were ever written, in either buffer: what a
  // display memory holding only the tiles this run draws on would need (a tile written only through its
  // apron is the model's copy of its neighbour's edge, not storage of its own).
  bool tile_ever_written(int face, int tx, int ty) const {
    const auto& e = ever_[static_cast<size_t>(face)];
    return !e.empty() && e[static_cast<size_t>(ty * tiles_per_row_ + tx)] != 0;
  }
  int64_t tiles_ever_written() const;
  // The most tiles whose own texels were written, the two buffers together, at any time in the run: the slots
  // a tile pool both buffers share would need for what this run drew (a tile leaves a buffer when it is cleared).
  int64_t tiles_most_at_once() const { return most_at_once_; }
  int64_t front_own_tiles() const { return buffers_[front_].own_tiles; }  // the image shown's: slots it takes in a pool
  void clear_back();  // the back buffer becomes empty and frees its tiles
  void commit() { committed_ = true; }
  bool committed() const { return committed_; }
  // Vertical blank: swaps if the host has committed; returns whether it did.
  bool vblank();

  // Pipeline port (front buffer).
  uint64_t read(int face, int x, int y) const { return fetch(front_, face, x, y); }
  // The front buffer's tile pool: tile t holds words [t * 1089, (t + 1) * 1089); tile 0 is empty.
  const uint64_t* front_pool() const { return pool(front_); }
  // The front buffer's tile numbers of one face, row-major by tile (never null; 0 where never written).
  const int32_t* front_tile_index(int face) const { return index(front_, face); }
  int tiles_per_row() const { return tiles_per_row_; }
  // Whether the front buffer's tiles lie in its pool in table order -- tile k of face f (row-major, faces
  // +X .. -Z) is pool tile front_tile_index(0)[0] + f x tiles-per-face + k, every tile written -- as a
  // whole cube stored face by face leaves them: a texel's place is then arithmetic (the functional model's
  // several-memory passes read without the table).
  bool front_tiles_in_order() const;
  // Whether any texel of this face of the front buffer was written (an
  // unwritten face reads empty everywhere and can never win composition).
  bool front_face_written(int face) const { return !buffers_[front_].index[face].empty(); }

  size_t tiles_allocated() const;  // written tiles, both buffers
  size_t bytes_allocated() const;  // tile pools (capacity) and per-face tile tables, both buffers

 private:
  struct Buffer {
    std::array<std::vector<int32_t>, 6> index;  // empty vector: face never written
    std::vector<uint64_t> pool;                 // empty until the first write; then tile 0 is the empty tile
    std::array<std::vector<uint8_t>, 6> own;    // per face, row-major by tile: 1 once its own texels are written here
    int64_t own_tiles = 0;                      // how many are 1
    std::array<std::vector<uint8_t>, 6> refused;  // per face, row-major by tile: 1 once the pool had no slot for it
    std::array<bool, 6> any_refused{};
  };
  // Whether tile (tx, ty) stores its own texels in the back buffer: held (memory.tiles) and not refused a slot.
  bool holds_back(int face, int tx, int ty) const {
    if (!holds(face, tx, ty)) return false;
    const auto& r = buffers_[back_].refused[static_cast<size_t>(face)];
    return r.empty() || r[static_cast<size_t>(ty * tiles_per_row_ + tx)] == 0;
  }
  // A held tile whose own texels are not yet stored in the back buffer asks the pool for a slot: false (and the
  // tile refused until the buffer is cleared) when every slot is taken. `pending`: slots promised but not yet
  // marked (reserve_faces). Always true without a pool.
  bool take_slot(int face, int tx, int ty, int64_t pending = 0);
  bool own_here(int face, int tx, int ty) const {  // its own texels written in the back buffer
    const auto& o = buffers_[back_].own[static_cast<size_t>(face)];
    return !o.empty() && o[static_cast<size_t>(ty * tiles_per_row_ + tx)] != 0;
  }
  const int32_t* index(int buf, int face) const {
    const auto& t = buffers_[buf].index[face];
    return t.empty() ? empty_index_.data() : t.data();
  }
  const uint64_t* pool(int buf) const {
    const auto& p = buffers_[buf].pool;
    return p.empty() ? empty_tile_.data() : p.data();
  }
  uint64_t fetch(int buf, int face, int x, int y) const {
    const int32_t t = index(buf, face)[(y >> kTileShift) * tiles_per_row_ + (x >> kTileShift)];
    return pool(buf)[static_cast<size_t>(t) * kTileWords + static_cast<size_t>(tile_word(x & (kTile - 1), y & (kTile - 1)))];
  }
  // The pool number of tile (tx, ty) of a face in the back buffer, allocating it (with its apron) if new.
  int32_t back_tile(int face, int tx, int ty);
  // Whether any word of the S x S face `words` in tile (tx, ty)'s window (its texels and apron) is not `skip`.
  // Words of tiles the bank does not hold count as skipped, here and below.
  bool window_written(int face, const uint64_t* words, int tx, int ty, uint64_t skip) const;
  void put(int face, int tx, int ty, int lx, int ly, uint64_t word);
  void mark_own(int face, int tx, int ty);  // its own texels written in the back buffer (and so ever)
  // Whether any of the S x S face `words`' own texels of tile (tx, ty) (no apron) is not `skip`.
  bool own_written(const uint64_t* words, int tx, int ty, uint64_t skip) const;
  bool apron_written(int face, const uint64_t* words, int tx, int ty, uint64_t skip) const;
  int64_t own_count(const uint64_t* words, int tx, int ty, uint64_t skip) const;  // own texels not `skip'
  // store_face's copy of one tile's window when the bank does not hold some of the tiles it draws from.
  void store_window_held(int face, const uint64_t* words, int tx, int ty, uint64_t skip, uint64_t* out) const;

  MemoryFormat fmt_;
  int tiles_per_row_;
  TileMap tiles_;
  std::array<bool, 6> face_sparse_{};  // a face present with some tile not held
  bool tile_sparse_ = false;           // any face so
  std::vector<uint64_t> empty_tile_;   // what tile 0 reads as before a buffer has a pool
  std::vector<int32_t> empty_index_;   // the tile table of a never-written face: all tile 0
  int64_t lost_ = 0;
  int64_t lost_tiles_ = 0;
  int64_t lost_pool_ = 0;
  int64_t pool_slots_ = 0;
  int64_t written_ = 0;
  int64_t most_at_once_ = 0;
  std::array<std::vector<uint8_t>, 6> ever_;  // per face, row-major by tile: 1 once its own texels were written
  std::array<Buffer, 2> buffers_;
  int front_ = 0, back_ = 1;
  bool committed_ = false;
};

// The memories of a whole HMD: for each eye (its cube rendered from that eye's
// position), `count` banks. Memory 0 is the fastest-updated.
class DisplayMemorySet {
 public:
  DisplayMemorySet(const MemoryConfig& m, int eyes);  // std::invalid_argument for a malformed memory.tiles
  const std::vector<std::string>& tiles_text() const { return tiles_; }
  int eyes() const { return eyes_; }
  int count() const { return count_; }
  const MemoryFormat& format() const { return fmt_; }
  DisplayMemoryBank& bank(int eye, int memory) { return *banks_[static_cast<size_t>(eye * count_ + memory)]; }
  const DisplayMemoryBank& bank(int eye, int memory) const {
    return *banks_[static_cast<size_t>(eye * count_ + memory)];
  }
  void vblank();  // every bank
  size_t bytes_allocated() const;
  size_t tiles_allocated() const;  // written tiles, every bank
  int64_t writes_lost() const;     // texels written to absent faces (memory.faces), every bank
  int64_t writes_lost_off_tiles() const;  // texels written to tiles not held (memory.tiles), every bank
  int64_t writes_lost_pool_full() const;  // texels written to tiles their pool had no slot for (memory.tile_pool), every bank
  int64_t texels_written() const;  // texels stored (host renders and preloads), every bank, ever
  int64_t tiles_ever_written(int memory) const;  // DisplayMemoryBank::tiles_ever_written, memory's banks (every eye)
  int64_t tiles_most_at_once(int memory) const;  // DisplayMemoryBank::tiles_most_at_once, the most of memory's banks

 private:
  MemoryFormat fmt_;
  std::vector<std::string> tiles_;  // memory.tiles
  int eyes_, count_;
  std::vector<std::unique_ptr<DisplayMemoryBank>> banks_;
};

// Whether a memory set is the one a configuration describes: its eyes,
// memory count, format (what a frame renderer reads it with), tiles held and tile pools.
bool matches(const DisplayMemorySet& mem, const ArpConfig& c);

}  // namespace arp::dp
