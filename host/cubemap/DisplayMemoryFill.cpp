#include "DisplayMemoryFill.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "CubeFaceBasis.hpp"

namespace arp::host {

void memory_texel_to_image(int face, int x, int y, int S, int& col, int& row) {
  const Dir3 d = memory_texel_direction(face, x, y, S);
  const FaceBasis& b = face_bases()[static_cast<size_t>(face)];
  auto dot = [&](const Dir3& a) { return d.x * a.x + d.y * a.y + d.z * a.z; };
  const double fw = dot(b.forward);
  const double u = (dot(b.right) / fw + 1.0) / 2.0, v = (1.0 - dot(b.up) / fw) / 2.0;
  // Texel centres map onto pixel centres exactly (a mirror of the grid), far from rounding boundaries.
  col = static_cast<int>(std::floor(u * S));
  row = static_cast<int>(std::floor(v * S));
}

namespace {

// The six faces' words in the memory's layout, face after face (every texel at `depth`).
std::vector<uint64_t> cube_words(const dp::MemoryFormat& fmt, const CubeMapImages& cm, uint32_t depth) {
  const int S = fmt.face_size;
  if (cm.face_size != S) throw std::invalid_argument("cube map face size differs from the display memory's");
  const size_t face_words = static_cast<size_t>(S) * static_cast<size_t>(S);
  std::vector<uint64_t> words(6 * face_words);
  for (int f = 0; f < 6; ++f) {
    uint64_t* w = words.data() + static_cast<size_t>(f) * face_words;
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        int col, row;
        memory_texel_to_image(f, x, y, S, col, row);
        const uint8_t* p = cm.faces[static_cast<size_t>(f)].px(col, row);
        w[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)] = (uint64_t{depth} << 32) | fmt.pack_rgb8(p[0], p[1], p[2]);
      }
  }
  return words;
}

// The six faces at once (reserve_faces, store_face: what write() does texel by texel, with the pool grown
// once by what they need instead of a quarter at a time, each growth a copy of everything before it).
// Every texel is written: `skip` has another depth code than all of them.
void store_cube(dp::DisplayMemoryBank& bank, const std::vector<uint64_t>& words, uint32_t depth) {
  const uint64_t skip = uint64_t{~depth} << 32;
  const size_t face_words = words.size() / 6;
  std::array<const uint64_t*, 6> faces{};
  for (size_t f = 0; f < 6; ++f) faces[f] = words.data() + f * face_words;
  bank.reserve_faces(faces, skip);
  for (int f = 0; f < 6; ++f) bank.store_face(f, faces[static_cast<size_t>(f)], skip);
}

}  // namespace

void fill_back_buffer(dp::DisplayMemoryBank& bank, const CubeMapImages& cm, uint32_t depth) {
  store_cube(bank, cube_words(bank.format(), cm, depth), depth);
}

void load_into_memories(dp::DisplayMemorySet& set, int memory, const CubeMapImages& cm, uint32_t depth,
                        bool swap_now) {
  std::vector<uint64_t> words;  // the same for every eye (one format a memory): made once
  for (int e = 0; e < set.eyes(); ++e) {
    auto& bank = set.bank(e, memory);
    bank.clear_back();
    if (words.empty()) words = cube_words(bank.format(), cm, depth);
    store_cube(bank, words, depth);
    bank.commit();
    if (swap_now) bank.vblank();
  }
}

}  // namespace arp::host
