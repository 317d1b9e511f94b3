#include "DisplayMemoryBank.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace arp::dp {

uint32_t MemoryFormat::pack_rgb8(int r8, int g8, int b8) const {
  auto q = [](int v8, int bits) {
    const uint32_t maxc = static_cast<uint32_t>((uint64_t{1} << bits) - 1);
    return static_cast<uint32_t>((static_cast<uint64_t>(std::clamp(v8, 0, 255)) * maxc * 2 + 255) / 510);
  };
  return pack_color(q(r8, red_bits), q(g8, green_bits), q(b8, blue_bits));
}

DisplayMemoryBank::DisplayMemoryBank(const MemoryFormat& f)
    : fmt_(f), tiles_per_row_((f.face_size + kTile - 1) / kTile), empty_tile_(new uint64_t[kTile * kTile]) {
  std::fill(empty_tile_.get(), empty_tile_.get() + kTile * kTile, fmt_.empty_word());
  empty_table_.assign(static_cast<size_t>(tiles_per_row_) * tiles_per_row_, empty_tile_.get());
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
  Buffer& b = buffers_[back_];
  auto& t = b.tables[face];
  if (t.empty()) t = empty_table_;
  uint64_t*& tile = t[static_cast<size_t>((y >> kTileShift) * tiles_per_row_ + (x >> kTileShift))];
  if (tile == empty_tile_.get()) {
    b.owned.emplace_back(new uint64_t[kTile * kTile]);
    tile = b.owned.back().get();
    std::fill(tile, tile + kTile * kTile, fmt_.empty_word());
  }
  tile[((y & (kTile - 1)) << kTileShift) + (x & (kTile - 1))] = (uint64_t{depth} << 32) | color;
}

void DisplayMemoryBank::clear_back() {
  Buffer& b = buffers_[back_];
  for (auto& t : b.tables) std::vector<uint64_t*>().swap(t);
  b.owned.clear();
  b.owned.shrink_to_fit();
}

bool DisplayMemoryBank::vblank() {
  if (!committed_) return false;
  std::swap(front_, back_);
  committed_ = false;
  return true;
}

size_t DisplayMemoryBank::tiles_allocated() const { return buffers_[0].owned.size() + buffers_[1].owned.size(); }

size_t DisplayMemoryBank::bytes_allocated() const {
  size_t bytes = tiles_allocated() * kTile * kTile * sizeof(uint64_t);
  for (const auto& b : buffers_)
    for (const auto& t : b.tables) bytes += t.size() * sizeof(uint64_t*);
  return bytes;
}

DisplayMemorySet::DisplayMemorySet(const MemoryConfig& m, int eyes) : fmt_(m), eyes_(eyes), count_(m.count) {
  for (int i = 0; i < eyes * m.count; ++i) banks_.push_back(std::make_unique<DisplayMemoryBank>(fmt_));
}

void DisplayMemorySet::vblank() {
  for (auto& b : banks_) b->vblank();
}

size_t DisplayMemorySet::bytes_allocated() const {
  size_t s = 0;
  for (const auto& b : banks_) s += b->bytes_allocated();
  return s;
}

}  // namespace arp::dp
