// A word-wise fingerprint: the hashes in reports (frames, memory contents) and
// the scene and motion hashes a plan records. Not cryptographic: it tells one
// input from another, it does not defend against a forger.
//
// Each word is folded in FNV-1a style (xor, then multiply by the FNV prime)
// and the state's high half shifted down onto its low half. Plain FNV-1a over
// 64-bit words only carries a difference upward (a product's bit k depends on
// the factors' bits 0..k), so two inputs differing in the top bits of two
// words -- a scene mirrored in x and in z, two signs flipped -- hashed alike.
// The shift sends every bit's difference below it, where the next multiply
// spreads it up again; value() ends with a full avalanche (MurmurHash3's
// 64-bit finaliser), so a difference in the last word reaches every bit too.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>

namespace arp {

class Fingerprint {
 public:
  Fingerprint& add(uint64_t v) {
    h_ = (h_ ^ v) * 0x100000001b3ull;
    h_ ^= h_ >> 32;
    return *this;
  }
  Fingerprint& add(double v) {  // by its bits: -0.0 and 0.0 differ, as the files that gave them do
    uint64_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    return add(u);
  }
  Fingerprint& add(const std::string& s) {
    add(static_cast<uint64_t>(s.size()));
    for (const char c : s) add(static_cast<uint64_t>(static_cast<unsigned char>(c)));
    return *this;
  }
  uint64_t value() const {
    uint64_t x = h_;
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    x ^= x >> 33;
    return x;
  }
  // As a configuration key holds it: positive and never 0 (0 there means "none"), and below 2^53, so that a JSON
  // tool holding numbers as doubles (jq, JavaScript) writes it back exactly: a plan edited with jq kept 63 bits
  // rounded, and its runs warned that it was planned for another scene and motion.
  int64_t key() const {
    const auto v = static_cast<int64_t>(value() >> 11);
    return v == 0 ? 1 : v;
  }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace arp
