#include "CompositionDepth.hpp"

#include <cmath>
#include <limits>

#include "host/render/CubeFaceRenderer.hpp"
#include "host/render/DepthCode.hpp"
#include "rtl_model/datapath/CompositionUnit.hpp"

namespace arp::sim {

int CompositionDepth::narrowest(int min_bits, int max_bits, double bound) const {
  if (share(max_bits) > bound) return 0;
  int w = max_bits;
  while (w > min_bits && share(w - 1) <= bound) --w;
  return w;
}

void add_composition_depth(const host::Scene& scene, const std::vector<int>& memory_of, int memories, double t_s,
                           const glm::dvec3& eye, int face_size, CompositionDepth& out) {
  const size_t M = static_cast<size_t>(memories);
  std::vector<std::vector<size_t>> objects(M);
  for (size_t i = 0; i < memory_of.size(); ++i) objects[static_cast<size_t>(memory_of[i])].push_back(i);
  const host::CubeFaceRenderer renderer;  // the run's own drawing and depth (radial distance)
  std::vector<std::vector<host::FaceImage>> faces(M);
  for (size_t m = 0; m < M; ++m)
    if (!objects[m].empty()) renderer.render_faces(scene, objects[m], t_s, eye, face_size, faces[m]);
  // The code at each width, and the composition unit's parameters for it (colour unused: 0).
  std::array<host::DepthCode, CompositionDepth::kMaxBits + 1> code;
  std::vector<dp::CompositionParams> params;
  params.reserve(code.size());
  for (int w = 0; w <= CompositionDepth::kMaxBits; ++w) {
    code[static_cast<size_t>(w)] = renderer.depth();
    code[static_cast<size_t>(w)].bits = std::max(w, 1);
    dp::MemoryFormat f;
    f.depth_bits = std::max(w, 1);
    params.emplace_back(f, std::array<int, 3>{0, 0, 0});
  }
  const double L = renderer.depth().log_range();
  constexpr double kEmpty = std::numeric_limits<double>::infinity();
  const size_t n = static_cast<size_t>(face_size) * static_cast<size_t>(face_size);
  std::vector<double> d(M);
  std::vector<uint64_t> words(M);
  for (size_t f = 0; f < 6; ++f)
    for (size_t k = 0; k < n; ++k) {
      int held = 0;
      size_t nearest = 0;
      for (size_t m = 0; m < M; ++m) {
        const auto& img = faces[m];
        d[m] = img.empty() || img[f].distance.empty() ? kEmpty : img[f].distance[k];
        held += d[m] < kEmpty ? 1 : 0;
        if (d[m] < d[nearest]) nearest = m;  // strict: of equal distances the lower memory
      }
      if (held < 2) continue;
      ++out.composed;
      // Codes grow with distance, so a lower memory can take the texel only by a tie, and only one holding a
      // surface; with none below the nearest, every width composes it right.
      bool contested = false;
      for (size_t m = 0; m < nearest; ++m) contested |= d[m] < kEmpty;
      if (!contested) continue;
      for (int w = 1; w <= CompositionDepth::kMaxBits; ++w) {
        const host::DepthCode& c = code[static_cast<size_t>(w)];
        for (size_t m = 0; m < M; ++m)
          words[m] = uint64_t{d[m] < kEmpty ? c.code(d[m], L) : params[static_cast<size_t>(w)].empty_depth} << 32;
        if (dp::compose(words.data(), memories, params[static_cast<size_t>(w)]).memory != static_cast<int>(nearest))
          ++out.wrong[static_cast<size_t>(w)];
      }
    }
  ++out.points;
}

}  // namespace arp::sim
