#include "DisplayMemoryBank.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace arp::dp {

uint32_t MemoryFormat::pack_rgb8(int r8, int g8, int b8) const {
  auto q = [](int v8, int bits) {
    if (bits == 8) return static_cast<uint32_t>(std::clamp(v8, 0, 255));  // (510 v + 255) / 510 = v
    const uint32_t maxc = static_cast<uint32_t>((uint64_t{1} << bits) - 1);
    return static_cast<uint32_t>((static_cast<uint64_t>(std::clamp(v8, 0, 255)) * maxc * 2 + 255) / 510);
  };
  return pack_color(q(r8, red_bits), q(g8, green_bits), q(b8, blue_bits));
}

DisplayMemoryBank::DisplayMemoryBank(const MemoryFormat& f, TileMap tiles, int64_t pool_slots)
    : fmt_(f),
      tiles_per_row_(tiles_per_row_of(f.face_size)),
      tiles_(std::move(tiles)),
      empty_tile_(kTileWords, f.empty_word()),
      empty_index_(static_cast<size_t>(tiles_per_row_) * tiles_per_row_, 0),
      pool_slots_(pool_slots) {
  if (pool_slots < 0) throw std::invalid_argument("DisplayMemoryBank: a tile pool of " + std::to_string(pool_slots) + " slots");
  if (tiles_.tiles_per_row() != 0 && tiles_.tiles_per_row() != tiles_per_row_)
    throw std::invalid_argument("DisplayMemoryBank: a tile map of " + std::to_string(tiles_.tiles_per_row()) +
                                " tiles a row for faces of " + std::to_string(tiles_per_row_));
  for (size_t face = 0; face < 6; ++face) {
    face_sparse_[face] = fmt_.present[face] && !tiles_.every_tile(static_cast<int>(face));
    tile_sparse_ |= face_sparse_[face];
  }
}

int32_t DisplayMemoryBank::back_tile(int face, int tx, int ty) {
  Buffer& b = buffers_[back_];
  constexpr size_t kWords = kTileWords;
  if (b.pool.empty()) b.pool.assign(kWords, fmt_.empty_word());  // tile 0: empty
  auto& t = b.index[face];
  if (t.empty()) t = empty_index_;
  const size_t slot = static_cast<size_t>(ty * tiles_per_row_ + tx);
  if (t[slot] != 0) return t[slot];
  const int32_t tile = static_cast<int32_t>(b.pool.size() / kWords);
  if (b.pool.size() + kWords > b.pool.capacity())  // grow by a quarter, not double: bounded slack
    b.pool.reserve(std::max(b.pool.size() + kWords, (b.pool.size() / kWords * 5 / 4 + 1) * kWords));
  b.pool.resize(b.pool.size() + kWords, fmt_.empty_word());
  t[slot] = tile;
  // The new tile's apron copies what its right, bottom and bottom-right neighbours already hold.
  const size_t base = static_cast<size_t>(tile) * kWords;
  auto neighbour = [&](int nx, int ny) -> int32_t {
    return (nx < tiles_per_row_ && ny < tiles_per_row_) ? t[static_cast<size_t>(ny * tiles_per_row_ + nx)] : 0;
  };
  if (const int32_t r = neighbour(tx + 1, ty))
    for (int ly = 0; ly < kTile; ++ly)
      b.pool[base + static_cast<size_t>(tile_word(kTile, ly))] = b.pool[static_cast<size_t>(r) * kWords + static_cast<size_t>(tile_word(0, ly))];
  if (const int32_t d = neighbour(tx, ty + 1))
    for (int lx = 0; lx < kTile; ++lx)
      b.pool[base + static_cast<size_t>(tile_word(lx, kTile))] = b.pool[static_cast<size_t>(d) * kWords + static_cast<size_t>(tile_word(lx, 0))];
  if (const int32_t c = neighbour(tx + 1, ty + 1))
    b.pool[base + static_cast<size_t>(tile_word(kTile, kTile))] = b.pool[static_cast<size_t>(c) * kWords];
  return tile;
}

void DisplayMemoryBank::put(int face, int tx, int ty, int lx, int ly, uint64_t word) {
  const int32_t tile = back_tile(face, tx, ty);
  buffers_[back_].pool[static_cast<size_t>(tile) * kTileWords + static_cast<size_t>(tile_word(lx, ly))] = word;
}

void DisplayMemoryBank::write(int face, int x, int y, uint32_t color, uint32_t depth) {
  const int S = fmt_.face_size;
  if (face < 0 || face >= 6 || x < 0 || x >= S || y < 0 || y >= S)
    throw std::out_of_range("display memory write outside the cube: face " + std::to_string(face) + " texel (" +
                            std::to_string(x) + "," + std::to_string(y) + ")");
  if (fmt_.color_bits_total() < 32 && (color >> fmt_.color_bits_total()) != 0)
    throw std::out_of_range("colour code wider than the memory's colour format");
  if (fmt_.depth_bits < 32 && (depth >> fmt_.depth_bits) != 0)
    throw std::out_of_range("depth code wider than the memory's depth format");
  if (!fmt_.present[static_cast<size_t>(face)]) {
    ++lost_;
    return;
  }
  const uint64_t word = (uint64_t{depth} << 32) | color;
  const int tx = x >> kTileShift, ty = y >> kTileShift, lx = x & (kTile - 1), ly = y & (kTile - 1);
  if (!holds(face, tx, ty)) {
    ++lost_tiles_;
    return;
  }
  if (!take_slot(face, tx, ty)) {
    ++lost_pool_;
    return;
  }
  ++written_;
  put(face, tx, ty, lx, ly, word);
  mark_own(face, tx, ty);
  // The texel also stands in the aprons of the tiles to its left, above, and above-left.
  if (lx == 0 && tx > 0) put(face, tx - 1, ty, kTile, ly, word);
  if (ly == 0 && ty > 0) put(face, tx, ty - 1, lx, kTile, word);
  if (lx == 0 && ly == 0 && tx > 0 && ty > 0) put(face, tx - 1, ty - 1, kTile, kTile, word);
}

bool DisplayMemoryBank::take_slot(int face, int tx, int ty, int64_t pending) {
  if (pool_slots_ == 0 || own_here(face, tx, ty)) return true;
  Buffer& b = buffers_[back_];
  const size_t k = static_cast<size_t>(ty * tiles_per_row_ + tx);
  auto& r = b.refused[static_cast<size_t>(face)];
  if (!r.empty() && r[k]) return false;
  if (buffers_[0].own_tiles + buffers_[1].own_tiles + pending < pool_slots_) return true;
  if (r.empty()) r.assign(static_cast<size_t>(tiles_per_row_) * static_cast<size_t>(tiles_per_row_), 0);
  r[k] = 1;
  b.any_refused[static_cast<size_t>(face)] = true;
  return false;
}

void DisplayMemoryBank::mark_own(int face, int tx, int ty) {
  const size_t tiles = static_cast<size_t>(tiles_per_row_) * static_cast<size_t>(tiles_per_row_), k = static_cast<size_t>(ty * tiles_per_row_ + tx);
  auto& e = ever_[static_cast<size_t>(face)];
  if (e.empty()) e.assign(tiles, 0);
  e[k] = 1;
  Buffer& b = buffers_[back_];
  auto& o = b.own[static_cast<size_t>(face)];
  if (o.empty()) o.assign(tiles, 0);
  if (o[k]) return;
  o[k] = 1;
  ++b.own_tiles;
  most_at_once_ = std::max(most_at_once_, buffers_[0].own_tiles + buffers_[1].own_tiles);
}

int64_t DisplayMemoryBank::tiles_ever_written() const {
  int64_t n = 0;
  for (const auto& e : ever_)
    for (const uint8_t b : e) n += b;
  return n;
}

int64_t DisplayMemoryBank::write_face(int face, const uint64_t* words, uint64_t skip) {
  if (face < 0 || face >= 6) throw std::out_of_range("display memory write outside the cube: face " + std::to_string(face));
  std::array<const uint64_t*, 6> one{};
  one[static_cast<size_t>(face)] = words;
  const int64_t stored = reserve_faces(one, skip);
  store_face(face, words, skip);
  return stored;
}

// Tile (tx, ty) holds texels x0 .. x0 + 32 and y0 .. y0 + 32 (its apron: the first column and row of the
// tiles to its right and below): it is touched iff a written texel lies in that window, as write() touches it.
bool DisplayMemoryBank::window_written(int face, const uint64_t* words, int tx, int ty, uint64_t skip) const {
  return (holds_back(face, tx, ty) && own_written(words, tx, ty, skip)) || apron_written(face, words, tx, ty, skip);
}

// Whether any word of tile (tx, ty)'s apron -- texel column x0 + 32 (rows y0 .. y0 + 31: the right
// neighbour's; row y0 + 32: the bottom-right's) and row y0 + 32 (columns x0 .. x0 + 31: the bottom
// neighbour's), within the face and of a tile the bank holds -- is not `skip`.
bool DisplayMemoryBank::apron_written(int face, const uint64_t* words, int tx, int ty, uint64_t skip) const {
  const int S = fmt_.face_size, x0 = tx * kTile, y0 = ty * kTile;
  const size_t row = static_cast<size_t>(S);
  const bool right = x0 + kTile < S, down = y0 + kTile < S;
  if (right && holds_back(face, tx + 1, ty))
    for (int y = y0; y < std::min(y0 + kTile, S); ++y)
      if (words[static_cast<size_t>(y) * row + static_cast<size_t>(x0 + kTile)] != skip) return true;
  if (right && down && holds_back(face, tx + 1, ty + 1) &&
      words[static_cast<size_t>(y0 + kTile) * row + static_cast<size_t>(x0 + kTile)] != skip)
    return true;
  if (down && holds_back(face, tx, ty + 1))
    for (int x = x0; x < std::min(x0 + kTile, S); ++x)
      if (words[static_cast<size_t>(y0 + kTile) * row + static_cast<size_t>(x)] != skip) return true;
  return false;
}

int64_t DisplayMemoryBank::own_count(const uint64_t* words, int tx, int ty, uint64_t skip) const {
  const int S = fmt_.face_size, x0 = tx * kTile, y0 = ty * kTile;
  const int w = std::min(kTile, S - x0), h = std::min(kTile, S - y0);
  int64_t n = 0;
  for (int ly = 0; ly < h; ++ly) {
    const uint64_t* row = words + static_cast<size_t>(y0 + ly) * static_cast<size_t>(S) + static_cast<size_t>(x0);
    for (int lx = 0; lx < w; ++lx) n += row[lx] != skip;
  }
  return n;
}

// Whether any word of the S x S face `words` among tile (tx, ty)'s own texels (no apron) is not `skip`.
bool DisplayMemoryBank::own_written(const uint64_t* words, int tx, int ty, uint64_t skip) const {
  const int S = fmt_.face_size, x0 = tx * kTile, y0 = ty * kTile;
  const int w = std::min(kTile, S - x0), h = std::min(kTile, S - y0);
  for (int ly = 0; ly < h; ++ly) {
    const uint64_t* row = words + static_cast<size_t>(y0 + ly) * static_cast<size_t>(S) + static_cast<size_t>(x0);
    bool any = false;
    for (int lx = 0; lx < w; ++lx) any |= row[lx] != skip;  // branch-free: vectorises
    if (any) return true;
  }
  return false;
}

int64_t DisplayMemoryBank::reserve_faces(const std::array<const uint64_t*, 6>& words, uint64_t skip) {
  const size_t n = static_cast<size_t>(fmt_.face_size) * static_cast<size_t>(fmt_.face_size);
  // A stored word has no bit above the colour's or the depth's width: one mask over the whole word.
  const uint64_t color_mask = fmt_.color_bits_total() < 32 ? ~((uint64_t{1} << fmt_.color_bits_total()) - 1) & 0xFFFFFFFFu : 0;
  const uint64_t depth_mask = fmt_.depth_bits < 32 ? ~((uint64_t{1} << fmt_.depth_bits) - 1) & 0xFFFFFFFFu : 0;
  const uint64_t wide = color_mask | (depth_mask << 32);
  std::array<int64_t, 6> count{};
  for (size_t f = 0; f < 6; ++f) {
    const uint64_t* w = words[f];
    if (!w) continue;
    uint64_t bad = 0;
    int64_t c = 0;
    for (size_t k = 0; k < n; ++k) {  // branch-free: vectorises
      const bool use = w[k] != skip;
      c += use;
      bad |= use ? w[k] & wide : 0;
    }
    if (bad & color_mask) throw std::out_of_range("colour code wider than the memory's colour format");
    if (bad) throw std::out_of_range("depth code wider than the memory's depth format");
    count[f] = c;
  }
  int64_t stored = 0, lost = 0, lost_off = 0, lost_pool = 0;
  std::vector<std::array<int, 3>> refused;  // tiles refused a slot by this call (undone if the allocation fails)
  if (pool_slots_ > 0) {  // slots first, face by face, tiles row-major: which tiles store their own texels
    int64_t promised = 0;
    for (size_t f = 0; f < 6; ++f) {
      if (!words[f] || !fmt_.present[f] || count[f] == 0) continue;
      for (int ty = 0; ty < tiles_per_row_; ++ty)
        for (int tx = 0; tx < tiles_per_row_; ++tx) {
          const int face = static_cast<int>(f);
          if (!holds(face, tx, ty) || own_here(face, tx, ty) || !own_written(words[f], tx, ty, skip)) continue;
          const bool was_refused = !holds_back(face, tx, ty);
          if (take_slot(face, tx, ty, promised)) {
            ++promised;
            continue;
          }
          if (!was_refused) refused.push_back({face, tx, ty});
          const int64_t texels = own_count(words[f], tx, ty, skip);
          count[f] -= texels;
          lost_pool += texels;
        }
    }
  }
  std::vector<std::array<int, 3>> fresh;  // (face, tx, ty) of the tiles to allocate, in write_face's order
  std::vector<std::array<int, 3>> drawn;  // (face, tx, ty) of the tiles whose own texels are written in this buffer anew
  for (size_t f = 0; f < 6; ++f) {
    if (!words[f]) continue;
    if (!fmt_.present[f]) {
      lost += count[f];
      continue;
    }
    if (face_sparse_[f] && count[f] > 0)
      for (int ty = 0; ty < tiles_per_row_; ++ty)  // the texels on tiles not held are lost
        for (int tx = 0; tx < tiles_per_row_; ++tx)
          if (!holds(static_cast<int>(f), tx, ty)) {
            const int64_t off = own_count(words[f], tx, ty, skip);
            count[f] -= off;
            lost_off += off;
          }
    stored += count[f];
    if (count[f] == 0) continue;
    const int32_t* table = index(back_, static_cast<int>(f));
    for (int ty = 0; ty < tiles_per_row_; ++ty)
      for (int tx = 0; tx < tiles_per_row_; ++tx) {
        const bool unallocated = table[ty * tiles_per_row_ + tx] == 0, unmarked = !own_here(static_cast<int>(f), tx, ty);
        if (!unallocated && !unmarked) continue;
        // Its own texels once; the apron (the next tile's first column and row) only if they are all skipped.
        const bool own = holds_back(static_cast<int>(f), tx, ty) && own_written(words[f], tx, ty, skip);
        if (own && unmarked) drawn.push_back({static_cast<int>(f), tx, ty});
        if (unallocated && (own || apron_written(static_cast<int>(f), words[f], tx, ty, skip)))
          fresh.push_back({static_cast<int>(f), tx, ty});
      }
  }
  // One growth for all the tiles (growing a quarter a tile copied the pool about four times over): exact
  // into an empty pool (a render's, after clear_back), by at least a quarter into a used one (repeated calls
  // stay linear).
  std::vector<uint64_t>& pool = buffers_[back_].pool;
  const size_t need = std::max(pool.size(), size_t{kTileWords}) + fresh.size() * kTileWords;
  try {
    if (!fresh.empty() && need > pool.capacity()) pool.reserve(std::max(need, pool.capacity() + pool.capacity() / 4));
  } catch (...) {
    for (const auto& t : refused)
      buffers_[back_].refused[static_cast<size_t>(t[0])][static_cast<size_t>(t[2] * tiles_per_row_ + t[1])] = 0;
    throw;
  }
  for (const auto& t : fresh) back_tile(t[0], t[1], t[2]);
  for (const auto& t : drawn) mark_own(t[0], t[1], t[2]);
  lost_ += lost;  // last: a failed allocation above leaves the counts as they were
  lost_tiles_ += lost_off;
  lost_pool_ += lost_pool;
  written_ += stored;
  return stored;
}

void DisplayMemoryBank::store_face(int face, const uint64_t* words, uint64_t skip) {
  if (face < 0 || face >= 6) throw std::out_of_range("display memory write outside the cube: face " + std::to_string(face));
  if (!fmt_.present[static_cast<size_t>(face)]) return;  // lost, and counted by reserve_faces
  const int S = fmt_.face_size;
  const int32_t* table = index(back_, face);
  uint64_t* pool = buffers_[back_].pool.data();
  for (int ty = 0; ty < tiles_per_row_; ++ty)
    for (int tx = 0; tx < tiles_per_row_; ++tx) {
      const int32_t tile = table[ty * tiles_per_row_ + tx];
      if (tile == 0) {  // the shared empty tile: never written
        if (window_written(face, words, tx, ty, skip))
          throw std::logic_error("DisplayMemoryBank::store_face: face " + std::to_string(face) + " tile (" + std::to_string(tx) +
                                 "," + std::to_string(ty) + ") was not reserved");
        continue;
      }
      uint64_t* out = pool + static_cast<size_t>(tile) * kTileWords;
      if (face_sparse_[static_cast<size_t>(face)] || buffers_[back_].any_refused[static_cast<size_t>(face)]) {
        store_window_held(face, words, tx, ty, skip, out);
        continue;
      }
      const int x0 = tx * kTile, y0 = ty * kTile;
      const int w = std::min(kTile + 1, S - x0), h = std::min(kTile + 1, S - y0);
      for (int ly = 0; ly < h; ++ly) {
        const uint64_t* row = words + static_cast<size_t>(y0 + ly) * static_cast<size_t>(S) + static_cast<size_t>(x0);
        uint64_t* dst = out + tile_word(0, ly);
        for (int lx = 0; lx < w; ++lx) dst[lx] = row[lx] == skip ? dst[lx] : row[lx];  // a blend: vectorises
      }
    }
}

// The window's four parts -- own texels, the right neighbour's column, the bottom neighbour's row, the
// bottom-right corner -- each copied only from a tile the bank holds.
void DisplayMemoryBank::store_window_held(int face, const uint64_t* words, int tx, int ty, uint64_t skip, uint64_t* out) const {
  const int S = fmt_.face_size, x0 = tx * kTile, y0 = ty * kTile;
  const int w = std::min(kTile, S - x0), h = std::min(kTile, S - y0);
  const bool right = x0 + kTile < S, down = y0 + kTile < S;
  const bool own = holds_back(face, tx, ty), col = right && holds_back(face, tx + 1, ty), row = down && holds_back(face, tx, ty + 1),
             corner = right && down && holds_back(face, tx + 1, ty + 1);
  auto copy = [&](int ly, int lx0, int n) {
    const uint64_t* src = words + static_cast<size_t>(y0 + ly) * static_cast<size_t>(S) + static_cast<size_t>(x0 + lx0);
    uint64_t* dst = out + tile_word(lx0, ly);
    for (int i = 0; i < n; ++i) dst[i] = src[i] == skip ? dst[i] : src[i];
  };
  for (int ly = 0; ly < h; ++ly) {
    if (own) copy(ly, 0, w);
    if (col) copy(ly, kTile, 1);
  }
  if (row) copy(kTile, 0, w);
  if (corner) copy(kTile, kTile, 1);
}

void DisplayMemoryBank::clear_back() {
  Buffer& b = buffers_[back_];
  for (auto& t : b.index) std::vector<int32_t>().swap(t);
  std::vector<uint64_t>().swap(b.pool);
  for (auto& o : b.own) std::fill(o.begin(), o.end(), uint8_t{0});
  b.own_tiles = 0;
  for (auto& r : b.refused) std::fill(r.begin(), r.end(), uint8_t{0});
  b.any_refused.fill(false);
}

bool DisplayMemoryBank::vblank() {
  if (!committed_) return false;
  std::swap(front_, back_);
  committed_ = false;
  return true;
}

size_t DisplayMemoryBank::tiles_allocated() const {
  size_t n = 0;
  for (const auto& b : buffers_)
    if (!b.pool.empty()) n += b.pool.size() / kTileWords - 1;
  return n;
}

size_t DisplayMemoryBank::bytes_allocated() const {
  size_t bytes = 0;
  for (const auto& b : buffers_) {
    bytes += b.pool.capacity() * sizeof(uint64_t);
    for (const auto& t : b.index) bytes += t.capacity() * sizeof(int32_t);
  }
  return bytes;
}

DisplayMemorySet::DisplayMemorySet(const MemoryConfig& m, int eyes)
    : fmt_(m), tiles_(m.tiles), eyes_(eyes), count_(m.count) {
  if (!m.tile_pool.empty() && static_cast<int>(m.tile_pool.size()) != count_)
    throw std::invalid_argument("memory.tile_pool has " + std::to_string(m.tile_pool.size()) + " numbers for " + std::to_string(count_) +
                                " memories (the configuration was not validated)");
  std::vector<TileMap> maps;
  if (std::string why; !tile_maps(m, maps, why)) throw std::invalid_argument("memory.tiles " + why + " (the configuration was not validated)");
  for (int e = 0; e < eyes; ++e)
    for (int k = 0; k < count_; ++k) banks_.push_back(std::make_unique<DisplayMemoryBank>(fmt_, maps[static_cast<size_t>(k)], m.pool_slots(k)));
}

void DisplayMemorySet::vblank() {
  for (auto& b : banks_) b->vblank();
}

size_t DisplayMemorySet::bytes_allocated() const {
  size_t s = 0;
  for (const auto& b : banks_) s += b->bytes_allocated();
  return s;
}

int64_t DisplayMemorySet::texels_written() const {
  int64_t n = 0;
  for (const auto& b : banks_) n += b->texels_written();
  return n;
}

int64_t DisplayMemorySet::writes_lost() const {
  int64_t n = 0;
  for (const auto& b : banks_) n += b->writes_lost();
  return n;
}

int64_t DisplayMemorySet::writes_lost_off_tiles() const {
  int64_t n = 0;
  for (const auto& b : banks_) n += b->writes_lost_off_tiles();
  return n;
}

int64_t DisplayMemorySet::writes_lost_pool_full() const {
  int64_t n = 0;
  for (const auto& b : banks_) n += b->writes_lost_pool_full();
  return n;
}

int64_t DisplayMemorySet::tiles_ever_written(int memory) const {
  int64_t n = 0;
  for (int e = 0; e < eyes_; ++e) n += bank(e, memory).tiles_ever_written();
  return n;
}

int64_t DisplayMemorySet::tiles_most_at_once(int memory) const {
  int64_t n = 0;
  for (int e = 0; e < eyes_; ++e) n = std::max(n, bank(e, memory).tiles_most_at_once());
  return n;
}

size_t DisplayMemorySet::tiles_allocated() const {
  size_t s = 0;
  for (const auto& b : banks_) s += b->tiles_allocated();
  return s;
}

bool matches(const DisplayMemorySet& mem, const ArpConfig& c) {
  const MemoryFormat& f = mem.format();
  const MemoryFormat want(c.memory);
  if (!(mem.eyes() == c.timing.eyes && mem.count() == c.memory.count && f.face_size == want.face_size &&
        f.red_bits == want.red_bits && f.green_bits == want.green_bits && f.blue_bits == want.blue_bits &&
        f.depth_bits == want.depth_bits && mem.tiles_text() == c.memory.tiles))
    return false;
  for (int k = 0; k < mem.count(); ++k)  // (no list and a list of zeros are the same: no pool)
    if (mem.bank(0, k).pool_slots() != c.memory.pool_slots(k)) return false;
  return true;
}

bool DisplayMemoryBank::front_tiles_in_order() const {
  const int32_t tpf = tiles_per_row_ * tiles_per_row_;
  const int32_t first = index(front_, 0)[0];
  if (first == 0) return false;  // tile 0 is the shared empty tile: not written
  for (int f = 0; f < 6; ++f) {
    const int32_t* t = index(front_, f);
    for (int32_t k = 0; k < tpf; ++k)
      if (t[k] != first + f * tpf + k) return false;
  }
  return true;
}

}  // namespace arp::dp
