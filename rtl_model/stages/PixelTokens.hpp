// What travels between the timed models' stages: one token per pixel-clock
// slot, carrying every eye scanned in that slot (both eyes of a lock-step
// stereo panel go through two copies of the datapath side by side).
#pragma once
#include <array>
#include <cstdint>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/CubeFaceAddressGenerator.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"

namespace arp::stage {

constexpr int kMaxEyes = 2;
constexpr int kMaxTaps = 4;  // bilinear; nearest uses tap 0

// Which pixel a token is, and when it must reach the panel. Padded to 32
// aligned bytes: copied as two whole 16-byte words, a copy's loads match the
// previous copy's stores (a 27-byte copy overlaps them and stalls store
// forwarding on every stage, measured at half the loosely timed level's time).
struct alignas(16) PixelSlot {
  int64_t frame = 0;
  int64_t slot_cycle = 0;  // pixel clock of its scan-out
  int32_t x = 0, y = 0;
  uint8_t eye_first = 0, eye_count = 1;
  bool latch = false;      // the orientation matrix unit loads its register for this pixel
  bool on_schedule = false;  // fast model: the speculative frame's colour holds for this pixel (FrameSpeculation)
  uint8_t reserved[4] = {};
};
static_assert(sizeof(PixelSlot) == 32, "PixelSlot must stay two 16-byte words");

struct LensToken {
  PixelSlot slot;
  dp::Vec3q view[kMaxEyes];  // head-frame direction
};

struct RotatedToken {
  PixelSlot slot;
  uint32_t sample;           // tracker sample in the matrix register
  dp::Vec3q world[kMaxEyes];
};

struct AddressToken {
  PixelSlot slot;
  uint32_t sample;
  dp::CubeAddress address[kMaxEyes];
};

struct FetchToken {
  PixelSlot slot;
  uint32_t sample;
  uint8_t memories = 0, taps = 0;                          // words in use per eye: taps x memories
  uint32_t wx[kMaxEyes], wy[kMaxEyes];                    // bilinear weights (0 when off)
  uint64_t words[kMaxEyes][kMaxTaps][dp::kCompositionInputs];  // texel words per eye, tap, memory
};

struct ComposedToken {
  PixelSlot slot;
  uint32_t sample;
  uint32_t wx[kMaxEyes], wy[kMaxEyes];
  uint32_t tap_color[kMaxEyes][kMaxTaps];
};

struct ColorToken {
  PixelSlot slot;
  uint32_t sample;
  uint32_t color[kMaxEyes];  // memory colour code
};

// A stage's output token: the pixel's slot and tracker sample passed on, then
// fn(k) for each eye the slot carries (both eyes of a lock-step stereo slot).
template <class In, class Out, class Fn>
inline void for_each_eye(const In& in, Out& out, Fn&& fn) {
  out.slot = in.slot;
  out.sample = in.sample;
  for (int k = 0; k < in.slot.eye_count; ++k) fn(k);
}

// Copying a token into a FIFO: whole, except the large fetch token, of which
// only the words in use are copied (the rest is never read).
template <class T>
inline void copy_token(T& dst, const T& src) {
  dst = src;
}
inline void copy_token(FetchToken& dst, const FetchToken& src) {
  dst.slot = src.slot;
  dst.sample = src.sample;
  dst.memories = src.memories;
  dst.taps = src.taps;
  for (int k = 0; k < src.slot.eye_count; ++k) {
    dst.wx[k] = src.wx[k];
    dst.wy[k] = src.wy[k];
    for (int t = 0; t < src.taps; ++t)
      for (int m = 0; m < src.memories; ++m) dst.words[k][t][m] = src.words[k][t][m];
  }
}

// What a waveform shows of a token leaving a stage (first eye): up to three
// values, named by probe_names().
inline void probe(const LensToken& t, std::array<int64_t, 3>& o) { o = {t.view[0].x, t.view[0].y, t.view[0].z}; }
inline void probe(const RotatedToken& t, std::array<int64_t, 3>& o) { o = {t.world[0].x, t.world[0].y, t.world[0].z}; }
inline void probe(const AddressToken& t, std::array<int64_t, 3>& o) { o = {t.address[0].face, t.address[0].x, t.address[0].y}; }
inline void probe(const FetchToken& t, std::array<int64_t, 3>& o) {
  o = {static_cast<int64_t>(t.words[0][0][0]), t.wx[0], t.wy[0]};
}
inline void probe(const ComposedToken& t, std::array<int64_t, 3>& o) { o = {t.tap_color[0][0], t.tap_color[0][1], t.wx[0]}; }
inline void probe(const ColorToken& t, std::array<int64_t, 3>& o) { o = {t.color[0], t.slot.x, t.slot.y}; }

}  // namespace arp::stage
