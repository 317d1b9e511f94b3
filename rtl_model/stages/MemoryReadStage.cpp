#include "MemoryReadStage.hpp"

#include "common/IntegerDivision.hpp"

namespace arp::stage {

BufferSwapper::BufferSwapper(const dp::ArpConfig& c, dp::DisplayMemorySet& mem, const HostWritePort* host,
                             int64_t hook_end, std::function<void(int64_t, double)> hook)
    : mem_(&mem), host_(host), timing_(c.timing), sched_(c), hook_(std::move(hook)), hook_end_(hook_end) {}

void BufferSwapper::tick(int64_t cycle) {
  swap_strobe = false;
  if (cycle < next_swap_ && cycle >= last_cycle_) {  // clocks only move forward: no swap before next_swap_
    last_cycle_ = cycle;
    return;
  }
  last_cycle_ = cycle;
  const int64_t F = timing_.frame_cycles();
  const int64_t f = floor_div(cycle - sched_.swap_cycle(0), F);
  next_swap_ = sched_.swap_cycle(f) >= cycle ? sched_.swap_cycle(f) : sched_.swap_cycle(f + 1);
  if (sched_.swap_cycle(f) != cycle) return;
  next_swap_ = sched_.swap_cycle(f + 1);
  swap_strobe = true;
  if (hook_ && f + 1 < hook_end_) {  // the host model updates the memories in this blank, before the next frame
    hook_(f + 1, timing_.frame_start_s(f + 1));
    ++host_calls_;
  }
  const int64_t now = timing_.cycles_to_ps(cycle);
  for (int e = 0; e < mem_->eyes(); ++e)
    for (int m = 0; m < mem_->count(); ++m) {
      dp::DisplayMemoryBank& b = mem_->bank(e, m);
      // Only what the write port committed, strictly before this blank (a host
      // model's own commits are its to swap).
      if (!b.committed() || !host_ || host_->commit_ps(e, m) == HostWritePort::kNever || host_->commit_ps(e, m) >= now) continue;
      b.vblank();
      ++swaps_;
      front_select ^= 1u << (e * mem_->count() + m);
    }
}

MemoryReadStage::MemoryReadStage(const StageContext& ctx)
    : RegisteredStage(ctx),
      mem_(*ctx.in.memories),
      swapper_(ctx.config(), mem_, nullptr, ctx.in.first_frame + ctx.in.frames, ctx.in.before_frame),
      memories_(ctx.config().memory.count),
      texel_frac_(ctx.config().widths.texel_frac),
      face_size_(ctx.config().memory.face_size),
      tiles_per_row_(dp::DisplayMemoryBank::tiles_per_row_of(face_size_)),
      bilinear_(ctx.config().pipeline.aa == dp::AaMode::Bilinear),
      empty_word_(mem_.format().empty_word()) {}

// Reads through the banks' published front-buffer tables (the same words
// DisplayMemoryBank::read returns), each memory's face table looked up once.
// Every tap lies in the stored tile of (x0, y0): x1 - x0 and y1 - y0 are 0 or
// 1, and a stored tile's apron holds its right and bottom neighbours' edges
// (DisplayMemoryBank). So a tap's place in a tile is found once per eye, and
// each memory costs one table lookup -- every memory has the face size.
void MemoryReadStage::compute(const AddressToken& in, FetchToken& t) const {
  if (bilinear_) fetch<true>(in, t);
  else fetch<false>(in, t);
}

// Bilinear: the taps a constant, so their loops unroll.
template <bool Bilinear>
void MemoryReadStage::fetch(const AddressToken& in, FetchToken& t) const {
  using Bank = dp::DisplayMemoryBank;
  constexpr int TM = Bank::kTile - 1;
  constexpr int kTaps = Bilinear ? 4 : 1;
  t.slot = in.slot;
  t.sample = in.sample;
  t.memories = static_cast<uint8_t>(memories_);
  t.taps = static_cast<uint8_t>(kTaps);
  for (int k = 0; k < in.slot.eye_count; ++k) {
    const int eye = in.slot.eye_first + k;
    const dp::CubeAddress& a = in.address[k];
    int32_t x0 = a.x, y0 = a.y;
    int32_t offset[kTaps] = {};  // each tap's word from the tile's word of (x0, y0)
    t.wx[k] = t.wy[k] = 0;
    if constexpr (Bilinear) {
      const dp::BilinearTaps b = dp::bilinear_taps(a.u, a.v, texel_frac_, face_size_);
      // Tap order x0y0, x1y0, x0y1, x1y1: the filter's c00, c10, c01, c11.
      x0 = b.x0;
      y0 = b.y0;
      const int32_t dx = b.x1 - b.x0, dy = (b.y1 - b.y0) * Bank::kTileStride;
      offset[1] = dx;
      offset[2] = dy;
      offset[3] = dy + dx;
      t.wx[k] = b.wx;
      t.wy[k] = b.wy;
    }
    const int32_t slot = (y0 >> Bank::kTileShift) * tiles_per_row_ + (x0 >> Bank::kTileShift);
    const size_t word = static_cast<size_t>(Bank::tile_word(x0 & TM, y0 & TM));
    uint32_t held = 0;
    for (int m = 0; m < memories_; ++m) {
      const Bank& bank = mem_.bank(eye, m);
      if (!bank.front_face_written(a.face)) {
        // Its table is all tile 0, the empty tile: no loads, and left out of the composition (held).
        // Memory 0's words are written all the same: the first word is the waveform's probe.
        if (m == 0)
          for (int i = 0; i < kTaps; ++i) t.words[k][i][0] = empty_word_;
        continue;
      }
      held |= 1u << m;
      const uint64_t* q = bank.front_pool() + static_cast<size_t>(bank.front_tile_index(a.face)[slot]) * Bank::kTileWords + word;
      for (int i = 0; i < kTaps; ++i) t.words[k][i][m] = q[offset[i]];
    }
    t.held[k] = static_cast<uint8_t>(held);
  }
}

}  // namespace arp::stage
