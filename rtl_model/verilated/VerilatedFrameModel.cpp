#include "VerilatedFrameModel.hpp"

#include <vector>

#include "common/InputError.hpp"

namespace arp::vl {

namespace {
const dp::ArpConfig& validated(const dp::ArpConfig& c) {
  const auto issues = dp::validate(c);
  if (!issues.empty()) throw InputError("configuration", issues.front().key, issues.front().reason);
  return c;
}
}  // namespace

VerilatedFrameModel::VerilatedFrameModel(const dp::ArpConfig& cfg)
    : cfg_(validated(cfg)),
      timing_(cfg.timing),
      lens_(cfg.lens, cfg.timing, cfg.widths.vec_frac),
      fmt_(cfg.memory),
      scan_(fmt_, cfg.pipeline),
      latch_(cfg),
      units_(make_units(cfg)) {}

void VerilatedFrameModel::render(const dp::DisplayMemorySet& mem, const dp::OrientationStream& orientation,
                                 int64_t frame, HmdFrame& out, bool photon_times) const {
  if (!dp::matches(mem, cfg_))
    throw InputError("display memories", "", "eyes, count, format, tiles (memory.tiles) or tile pools (memory.tile_pool) differ from the configuration");
  if (orientation.size() == 0) throw InputError("orientation", "", "no orientation samples");
  if (frame < 0) throw InputError("frame", "", "frame index must not be negative");
  const int W = lens_.width(), H = lens_.height(), E = lens_.eyes(), N = mem.count();
  const int T = cfg_.widths.texel_frac;
  const int32_t S = fmt_.face_size;
  const bool bilinear = cfg_.pipeline.aa == dp::AaMode::Bilinear;
  const int taps = bilinear ? 4 : 1;
  out.resize(W, H, E, photon_times);
  out.display_bits = scan_.display_bits();
  out.frame_index = frame;

  const size_t w = static_cast<size_t>(W);
  std::vector<dp::Mat3q> mats(w);
  std::vector<dp::Vec3q> lens(w), rot(w);
  std::vector<int32_t> face(w);
  std::vector<int64_t> u(w), v(w);
  std::vector<uint64_t> words(w * static_cast<size_t>(N));
  std::vector<dp::Composite> comp(w);
  std::vector<uint32_t> tap_colors(4 * w), wx(w), wy(w), color(w);
  std::vector<dp::BilinearTaps> quad(w);
  size_t cached_sample = SIZE_MAX;
  dp::Mat3q cached{};
  for (int eye = 0; eye < E; ++eye)
    for (int y = 0; y < H; ++y) {
      const int32_t *lx = lens_.row_x(eye, y), *ly = lens_.row_y(eye, y), *lz = lens_.row_z(eye, y);
      for (int x = 0; x < W; ++x) {
        const size_t s = latch_.sample(orientation, frame, eye, x, y);
        if (s != cached_sample) {
          cached = dp::quantise_rotation(orientation[s].q, cfg_.widths.mat_frac);
          cached_sample = s;
        }
        mats[static_cast<size_t>(x)] = cached;
        lens[static_cast<size_t>(x)] = {lx[x], ly[x], lz[x]};
      }
      units_.rotate->run(mats.data(), lens.data(), w, rot.data());
      units_.address->run(rot.data(), w, face.data(), u.data(), v.data());
      if (bilinear)
        for (size_t x = 0; x < w; ++x) {
          quad[x] = dp::bilinear_taps(u[x], v[x], T, S);
          wx[x] = quad[x].wx;
          wy[x] = quad[x].wy;
        }
      for (int k = 0; k < taps; ++k) {
        for (size_t x = 0; x < w; ++x) {
          int32_t tx = static_cast<int32_t>(u[x] >> T), ty = static_cast<int32_t>(v[x] >> T);
          if (bilinear) {
            tx = (k & 1) ? quad[x].x1 : quad[x].x0;
            ty = (k & 2) ? quad[x].y1 : quad[x].y0;
          }
          for (int m = 0; m < N; ++m) words[x * static_cast<size_t>(N) + static_cast<size_t>(m)] = mem.bank(eye, m).read(face[x], tx, ty);
        }
        units_.compose->run(words.data(), w, comp.data());
        for (size_t x = 0; x < w; ++x) tap_colors[4 * x + static_cast<size_t>(k)] = comp[x].color;
      }
      if (bilinear) {
        units_.filter->run(tap_colors.data(), wx.data(), wy.data(), w, color.data());
      } else {
        for (size_t x = 0; x < w; ++x) color[x] = tap_colors[4 * x];
      }
      uint32_t* dst = &out.pixels[out.index(eye, 0, y)];
      for (int x = 0; x < W; ++x) dst[x] = scan_.to_display(color[static_cast<size_t>(x)]);
      if (photon_times) {
        int64_t* ph = &out.photon_ps[out.index(eye, 0, y)];
        for (int x = 0; x < W; ++x) ph[x] = dp::HmdScanOut::photon_time_ps(timing_, cfg_.pipeline, frame, eye, x, y);
      }
    }
}

}  // namespace arp::vl
