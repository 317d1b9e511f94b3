// How wide a depth code several display memories need, measured: each memory's
// objects rendered from one point into float faces (host::CubeFaceRenderer, the
// run's renderer), every texel where two or more memories hold a surface
// composed by the composition unit's own rule (dp::compose: the smallest code
// wins, a tie goes to the lower memory) with the depth code at each width, and
// counted wrong where that winner is not the memory whose surface is nearest.
// A tie is right when the nearer surface is in the lower memory, so a ladder
// whose nearer surfaces are always in faster memories composes right at 1 bit.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "host/scene/Scene.hpp"

namespace arp::sim {

struct CompositionDepth {
  static constexpr int kMaxBits = 32;
  std::array<int64_t, kMaxBits + 1> wrong{};  // [w]: texels composed from the wrong memory at a w-bit code (w >= 1)
  int64_t composed = 0;                       // texels where two or more memories hold a surface
  int points = 0;                             // renders added
  // Wrong texels as a share of those composed (0 when nothing is).
  double share(int bits) const {
    return composed ? static_cast<double>(wrong[static_cast<size_t>(bits)]) / static_cast<double>(composed) : 0.0;
  }
  // The narrowest width from `min_bits` whose share, and every wider width's up to `max_bits`, is at most
  // `bound`; 0 when even `max_bits` exceeds it.
  int narrowest(int min_bits, int max_bits, double bound) const;
};

// Adds one point: memory_of[i] is object i's memory (0 .. memories - 1), the scene rendered at time t from
// `eye` at face size S.
void add_composition_depth(const host::Scene& scene, const std::vector<int>& memory_of, int memories, double t_s,
                           const glm::dvec3& eye, int face_size, CompositionDepth& out);

}  // namespace arp::sim
