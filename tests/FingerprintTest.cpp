// common/Fingerprint tells inputs apart wherever they differ. Plain FNV-1a over 64-bit words (what it was until
// 2026-11-28) carried a word's difference only upward, so two words differing in their top bits hashed alike:
// a scene or a walk mirrored in x and in z (two sign bits a point) hashed as the original, and a plan made for
// the mirror image was not told apart (plan.scene_hash, plan.motion_hash). Seen failing with the shift in add()
// dropped (the pairs below), and with value()'s finaliser dropped (a flip in the last word changes 2 bits).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/Fingerprint.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/scene/Gallery.hpp"
#include "host/scene/Scene.hpp"

namespace arp {
namespace {

uint64_t fingerprint(const std::vector<uint64_t>& words) {
  Fingerprint h;
  for (const uint64_t w : words) h.add(w);
  return h.value();
}

// Any two of five words flipped at the same bit, for every bit: no pair cancels (the old hash: every pair of
// top-bit flips did).
TEST(Fingerprint, TwoWordsFlippedAtTheSameBitHashApart) {
  const std::vector<uint64_t> base{0x3ff0000000000000ull, 0x4000000000000000ull, 0xbff8000000000000ull, 0, 12345};
  const uint64_t h0 = fingerprint(base);
  for (int bit = 0; bit < 64; ++bit)
    for (size_t i = 0; i < base.size(); ++i)
      for (size_t j = i + 1; j < base.size(); ++j) {
        std::vector<uint64_t> w = base;
        w[i] ^= uint64_t{1} << bit;
        w[j] ^= uint64_t{1} << bit;
        EXPECT_NE(fingerprint(w), h0) << "bit " << bit << ", words " << i << " and " << j;
      }
}

// One bit flipped anywhere, in the first word or the last, changes about half the hash's bits (a binomial(64, 1/2)
// is below 12 with probability about 1e-7): each bit of a key stands for the whole input.
TEST(Fingerprint, OneBitFlippedChangesAboutHalfTheBits) {
  const std::vector<uint64_t> base{1, 2, 3};
  const uint64_t h0 = fingerprint(base);
  for (const size_t word : {size_t{0}, base.size() - 1})
    for (int bit = 0; bit < 64; ++bit) {
      std::vector<uint64_t> w = base;
      w[word] ^= uint64_t{1} << bit;
      EXPECT_GE(__builtin_popcountll(fingerprint(w) ^ h0), 12) << "word " << word << ", bit " << bit;
    }
}

// A key (plan.scene_hash, plan.motion_hash) is below 2^53: a JSON tool that holds numbers as doubles (jq, JavaScript)
// writes it back as it read it. Seen failing with 63-bit keys (the key before 2026-11-28: jq rounded it).
TEST(Fingerprint, AKeySurvivesAToolThatReadsNumbersAsDoubles) {
  for (uint64_t i = 0; i < 1000; ++i) {
    const int64_t k = Fingerprint{}.add(i).key();
    EXPECT_GT(k, 0);
    EXPECT_LT(k, int64_t{1} << 53) << i;
    EXPECT_EQ(static_cast<int64_t>(static_cast<double>(k)), k) << i;
  }
}

// What a plan records: the gallery, and its walk, mirrored in x and in z are another scene and another walk.
TEST(Fingerprint, AMirroredSceneAndWalkAreOthers) {
  const host::Scene gallery = host::make_gallery();
  host::Scene mirrored = gallery;
  for (host::SceneObject& o : mirrored.objects) {
    o.position.x = -o.position.x;
    o.position.z = -o.position.z;
  }
  EXPECT_NE(host::scene_hash(mirrored), host::scene_hash(gallery));
  std::vector<glm::dvec3> points = host::gallery_walk(), back = points;
  for (glm::dvec3& p : back) {
    p.x = -p.x;
    p.z = -p.z;
  }
  EXPECT_NE(host::walk_hash(host::WalkPath(back, 1.0, "mirrored")), host::walk_hash(host::WalkPath(points, 1.0, "gallery walk")));
}

}  // namespace
}  // namespace arp
