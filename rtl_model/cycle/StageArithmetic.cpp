#include "StageArithmetic.hpp"

namespace arp::cycle {

StageArithmetic::StageArithmetic(const dp::ArpConfig& c)
    : cfg_(c),
      lens_(c.lens, c.timing, c.widths.vec_frac),
      rot_(c.widths),
      addr_(c.widths, c.memory.face_size),
      fmt_(c.memory),
      comp_(fmt_, c.memory.background),
      layout_(fmt_),
      scan_(fmt_, c.pipeline),
      bilinear_(c.pipeline.aa == dp::AaMode::Bilinear),
      memo_(dp::tabulate_aligned_reciprocal(addr_, c.widths)),
      memo_ptr_(memo_.empty() ? nullptr : memo_.data()) {}

// Reads through the banks' published front-buffer tables (the same words
// DisplayMemoryBank::read returns), each memory's face table looked up once.
void StageArithmetic::fetch(const AddressToken& in, const dp::DisplayMemorySet& mem, FetchToken& t) const {
  using Bank = dp::DisplayMemoryBank;
  t.slot = in.slot;
  t.sample = in.sample;
  const int n = cfg_.memory.count;
  t.memories = static_cast<uint8_t>(n);
  t.taps = static_cast<uint8_t>(bilinear_ ? 4 : 1);
  for (int k = 0; k < in.slot.eye_count; ++k) {
    const int eye = in.slot.eye_first + k;
    const dp::CubeAddress& a = in.address[k];
    int32_t tx[kMaxTaps] = {a.x}, ty[kMaxTaps] = {a.y};
    t.wx[k] = t.wy[k] = 0;
    int taps = 1;
    if (bilinear_) {
      const dp::BilinearTaps b = dp::bilinear_taps(a.u, a.v, cfg_.widths.texel_frac, fmt_.face_size);
      // Tap order x0y0, x1y0, x0y1, x1y1: the filter's c00, c10, c01, c11.
      tx[0] = b.x0; ty[0] = b.y0;
      tx[1] = b.x1; ty[1] = b.y0;
      tx[2] = b.x0; ty[2] = b.y1;
      tx[3] = b.x1; ty[3] = b.y1;
      t.wx[k] = b.wx;
      t.wy[k] = b.wy;
      taps = 4;
    }
    for (int m = 0; m < n; ++m) {
      const Bank& bank = mem.bank(eye, m);
      const int32_t* index = bank.front_tile_index(a.face);
      const uint64_t* pool = bank.front_pool();
      const int tpr = bank.tiles_per_row();
      for (int i = 0; i < taps; ++i) {
        const int32_t tile = index[(ty[i] >> Bank::kTileShift) * tpr + (tx[i] >> Bank::kTileShift)];
        t.words[k][i][m] = pool[static_cast<size_t>(tile) * Bank::kTileWords +
                                static_cast<size_t>(Bank::tile_word(tx[i] & (Bank::kTile - 1), ty[i] & (Bank::kTile - 1)))];
      }
    }
  }
}

}  // namespace arp::cycle
