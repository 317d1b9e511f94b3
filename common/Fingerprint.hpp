// A word-wise FNV-1a style fingerprint: the hashes in reports (frames, memory
// contents) and the scene hash a plan records. Not cryptographic: it tells
// one input from another, it does not defend against a forger.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>

namespace arp {

class Fingerprint {
 public:
  Fingerprint& add(uint64_t v) {
    h_ = (h_ ^ v) * 0x100000001b3ull;
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
  uint64_t value() const { return h_; }
  // As a configuration key holds it: positive and never 0 (0 there means "none").
  int64_t key() const {
    const auto v = static_cast<int64_t>(h_ >> 1);
    return v == 0 ? 1 : v;
  }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace arp
