#include "FunctionalModel.hpp"

#include <omp.h>

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "common/InputError.hpp"

namespace arp {

using namespace dp;

namespace {

const ArpConfig& validated(const ArpConfig& c) {
  const auto issues = validate(c);
  if (!issues.empty()) throw InputError("configuration", issues.front().key, issues.front().reason);
  return c;
}

}  // namespace

// Splits one scanline into runs that see the same orientation sample. Only
// the per-pixel latch can produce more than one run.
void latch_segments(const LatchRule& rule, const OrientationStream& o, int64_t frame, int eye, int y, int width,
                    std::vector<LatchSegment>& out) {
  out.clear();
  auto sample_at = [&](int x) { return rule.sample(o, frame, eye, x, y); };
  const size_t first = sample_at(0), last = sample_at(width - 1);
  if (first == last) {
    out.push_back({0, width, first});
    return;
  }
  int x0 = 0;
  size_t cur = first;
  while (x0 < width) {
    // First x in (x0, width) whose sample differs from cur; the sample index never decreases along a line.
    int lo = x0 + 1, hi = width;
    while (lo < hi) {
      const int mid = lo + (hi - lo) / 2;
      if (sample_at(mid) != cur) hi = mid; else lo = mid + 1;
    }
    out.push_back({x0, lo, cur});
    if (lo < width) cur = sample_at(lo);
    x0 = lo;
  }
}


FunctionalModel::FunctionalModel(const ArpConfig& cfg)
    : cfg_(validated(cfg)),
      timing_(cfg.timing),
      lens_(cfg.lens, cfg.timing, cfg.widths.vec_frac),
      addr_(cfg.widths, cfg.memory.face_size),
      rot_(cfg.widths),
      fmt_(cfg.memory),
      comp_(fmt_, cfg.memory.background),
      layout_(fmt_),
      scan_(fmt_, cfg.pipeline),
      latch_(cfg) {
  // Tabulate the reciprocal unit when its domain is small and its output fits 32 bits.
  memo_ = tabulate_aligned_reciprocal(addr_, cfg_.widths);
  if (!memo_.empty()) memo_view_.aligned = memo_.data();
  // The narrow loops where the configuration's bounds fit 32 bits (the same results; tests/FunctionalModelTest).
  memo_view_.int32_lanes = address_fits_int32(addr_, memo_);
  rotate_int32_ = rotate_fits_int32(cfg_.widths, lens_.max_abs_component());
}

void FunctionalModel::render(const DisplayMemorySet& mem, const OrientationStream& orientation, int64_t frame,
                             HmdFrame& out, const RenderOptions& opt) const {
  if (!matches(mem, cfg_))
    throw InputError("display memories", "", "eyes, count, format, tiles (memory.tiles) or tile pools (memory.tile_pool) differ from the configuration");
  if (orientation.size() == 0) throw InputError("orientation", "", "no orientation samples");
  if (frame < 0) throw InputError("frame", "", "frame index must not be negative");
  const bool bilinear = cfg_.pipeline.aa == AaMode::Bilinear;
  if (cfg_.widths.divider == DividerKind::Exact) {
    if (bilinear) render_impl<DividerKind::Exact, AaMode::Bilinear>(mem, orientation, frame, out, opt);
    else render_impl<DividerKind::Exact, AaMode::Off>(mem, orientation, frame, out, opt);
  } else {
    if (bilinear) render_impl<DividerKind::ReciprocalLut, AaMode::Bilinear>(mem, orientation, frame, out, opt);
    else render_impl<DividerKind::ReciprocalLut, AaMode::Off>(mem, orientation, frame, out, opt);
  }
}

passes::EyeSources FunctionalModel::eye_sources(const DisplayMemorySet& mem, int e, std::vector<std::vector<int32_t>>& flat) {
  const int tpr = mem.bank(0, 0).tiles_per_row(), tpf = tpr * tpr;
  passes::EyeSources es;
  es.tiles_per_row = tpr;
  es.tiles_per_face = tpf;
  bool dense = true;  // every memory's tiles in table order (see passes::EyeSources::dense)
  for (int m = 0; m < mem.count(); ++m) {
    const DisplayMemoryBank& b = mem.bank(e, m);
    bool any = false;
    for (int face = 0; face < 6; ++face) any = any || b.front_face_written(face);
    if (!any) continue;
    flat.emplace_back(static_cast<size_t>(6) * tpf);
    for (int face = 0; face < 6; ++face) {
      const int32_t* tiles = b.front_tile_index(face);
      for (int k = 0; k < tpf; ++k)  // tile numbers -> word offsets into the pool
        flat.back()[static_cast<size_t>(face * tpf + k)] = tiles[k] * DisplayMemoryBank::kTileWords;
    }
    es.pool[es.count] = b.front_pool();
    es.offset[es.count] = flat.back().data();
    es.dense_base[es.count] = b.front_pool() + flat.back()[0];
    dense = dense && b.front_tiles_in_order();
    ++es.count;
  }
  es.dense = dense && es.count > 0;
  return es;
}

template <DividerKind D, AaMode A>
void FunctionalModel::render_impl(const DisplayMemorySet& mem, const OrientationStream& orientation,
                                  int64_t frame, HmdFrame& out, const RenderOptions& opt) const {
  const int W = lens_.width(), H = lens_.height(), E = lens_.eyes(), N = mem.count();
  const int32_t S = fmt_.face_size;
  const int T = cfg_.widths.texel_frac;
  const auto& pc = cfg_.pipeline;

  // The orientation register can only hold samples between the frame's first
  // latch and the start of the next frame; quantise each once.
  // (Plain variables, not a structured binding: the render lambdas capture
  // s_lo, which clang before 16 does not allow for a binding.)
  const auto samples = latch_.frame_samples(orientation, frame);
  const size_t s_lo = samples.first, s_hi = samples.second;
  std::vector<Mat3q> mats;
  for (size_t s = s_lo; s <= s_hi; ++s) mats.push_back(quantise_rotation(orientation[s].q, cfg_.widths.mat_frac));

  // Word offsets of tiles are int32: the largest buffer (6 faces of 16384^2
  // texels, plus the empty tile) ends below 2^31 words.
  static_assert((int64_t{6} * 512 * 512 + 1) * DisplayMemoryBank::kTileWords < INT32_MAX,
                "tile word offsets must fit int32 for the largest face_size");
  // Per eye, the memories holding anything (see eye_sources).
  std::vector<passes::EyeSources> sources(static_cast<size_t>(E));
  std::vector<std::vector<int32_t>> flat;
  flat.reserve(static_cast<size_t>(E) * N);  // (the sources point into its vectors, whose buffers stay put as it grows)
  for (int e = 0; e < E; ++e) sources[static_cast<size_t>(e)] = eye_sources(mem, e, flat);

  out.resize_to_overwrite(W, H, E, opt.photon_times);  // every pixel and photon time is written below
  out.display_bits = scan_.display_bits();
  out.frame_index = frame;
  const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();

#pragma omp parallel num_threads(threads)
  {
    // Per-thread buffers for one chunk of a line (4 KiB): with the passes' own blocks (at most about
    // 21 KiB, four memories bilinear) every pass works out of a 32 KiB L1.
    constexpr int C = 128;
    const size_t w = C;
    std::vector<LatchSegment> segs;
    std::vector<int32_t> rx(w), ry(w), rz(w), face(w), u(w), v(w);
    std::vector<int32_t> tiles(w), words(w);  // the nearest texels' places, several memories
    const passes::TexelRef ref{tiles.data(), words.data()};
    ClockTimeCursor clock(timing_.config().pixel_clock_hz);  // a line's slots are consecutive clocks: no division each
#pragma omp for schedule(dynamic, 16)
    for (int line = 0; line < E * H; ++line) {
      const int eye = line / H, y = line % H;
      const passes::EyeSources& src = sources[static_cast<size_t>(eye)];
      latch_segments(latch_, orientation, frame, eye, y, W, segs);
      uint32_t* dst_line = &out.pixels[out.index(eye, 0, y)];
      for (int c0 = 0; c0 < W; c0 += C) {
        const int n = std::min(C, W - c0);
        for (const LatchSegment& sg : segs) {
          const int a = std::max(sg.x0, c0), b = std::min(sg.x1, c0 + n);
          if (a < b)
            passes::rotate_line(mats[sg.sample - s_lo], lens_.row_x(eye, y) + c0, lens_.row_y(eye, y) + c0,
                                lens_.row_z(eye, y) + c0, a - c0, b - c0, rot_, rotate_int32_, rx.data(), ry.data(), rz.data());
        }
        if constexpr (D == DividerKind::ReciprocalLut)
          passes::address_line_lut(rx.data(), ry.data(), rz.data(), n, addr_, memo_view_, face.data(), u.data(), v.data());
        else
          passes::address_line_exact(rx.data(), ry.data(), rz.data(), n, addr_, face.data(), u.data(), v.data());
        uint32_t* dst = dst_line + c0;
        if constexpr (A == AaMode::Bilinear) {
          passes::bilinear_memories_line(src, face.data(), u.data(), v.data(), n, T, S, layout_, comp_, dst);
        } else if (src.count == 1) {  // one memory: the fused single-memory pass
          passes::nearest_single_memory_line(src, face.data(), u.data(), v.data(), n, T, comp_, dst);
        } else {
          passes::nearest_refs_line(face.data(), u.data(), v.data(), n, T, src, ref);
          passes::fetch_compose_line(src, ref, n, comp_, dst);
        }
        if (!scan_.identity())
          for (int x = 0; x < n; ++x) dst[x] = scan_.to_display(dst[x]);
      }
      if (opt.photon_times)
        HmdScanOut::photon_times_ps(clock, timing_, pc, frame, eye, y, W, &out.photon_ps[out.index(eye, 0, y)]);
    }
  }
}

}  // namespace arp
