// What travels between the timed models' stages: one token per pixel-clock
// slot, carrying every eye scanned in that slot (both eyes of a lock-step
// stereo panel go through two copies of the datapath side by side).
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

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
  // Per eye, the memories whose words were read (bit m: memory m); the others' faces were never
  // written, so they read as empty and cannot win the composition (dp::compose_held). All in a token
  // built elsewhere (a bench's); set by every fetch. A token the fast level passes on without a fetch
  // (FrameSpeculation: memories = taps = 0) keeps a stale mask and is never composed.
  uint8_t held[kMaxEyes] = {0xff, 0xff};
  uint32_t wx[kMaxEyes], wy[kMaxEyes];                    // bilinear weights (0 when off)
  uint64_t words[kMaxEyes][kMaxTaps][dp::kCompositionInputs];  // texel words per eye, tap, memory
};

static_assert(dp::kCompositionInputs <= 8, "FetchToken::held has a bit per memory");

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
// only the taps in use are copied (the rest is never read): each a whole row
// of kCompositionInputs words, a few vector moves, rather than word by word;
// one word a tap where only memory 0 was read.
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
    dst.held[k] = src.held[k];
    dst.wx[k] = src.wx[k];
    dst.wy[k] = src.wy[k];
    // A tap's row in two fixed sizes (memcpy of a constant size is a few vector moves): the first half
    // holds every word in use up to half the composition unit's inputs.
    constexpr size_t kRow = sizeof src.words[k][0], kHalf = kRow / 2;
    if (src.held[k] <= 1) {  // memory 0 read, or none (memory 0's words are written all the same): one word a tap
      for (int t = 0; t < src.taps; ++t) dst.words[k][t][0] = src.words[k][t][0];
    } else if (2 * src.memories <= dp::kCompositionInputs) {
      for (int t = 0; t < src.taps; ++t) std::memcpy(dst.words[k][t], src.words[k][t], kHalf);
    } else {
      for (int t = 0; t < src.taps; ++t) std::memcpy(dst.words[k][t], src.words[k][t], kRow);
    }
  }
}

// What a waveform shows of a token leaving a stage (first eye): three values,
// named by the stage's StageInfo probes, f(value) for each in order.
template <class F>
void for_each_probe_field(const LensToken& t, F&& f) {
  f(t.view[0].x), f(t.view[0].y), f(t.view[0].z);
}
template <class F>
void for_each_probe_field(const RotatedToken& t, F&& f) {
  f(t.world[0].x), f(t.world[0].y), f(t.world[0].z);
}
template <class F>
void for_each_probe_field(const AddressToken& t, F&& f) {
  f(t.address[0].face), f(t.address[0].x), f(t.address[0].y);
}
template <class F>
void for_each_probe_field(const FetchToken& t, F&& f) {
  f(t.words[0][0][0]), f(t.wx[0]), f(t.wy[0]);
}
template <class F>
void for_each_probe_field(const ComposedToken& t, F&& f) {
  f(t.tap_color[0][0]), f(t.tap_color[0][1]), f(t.wx[0]);
}
template <class F>
void for_each_probe_field(const ColorToken& t, F&& f) {
  f(t.color[0]), f(t.slot.x), f(t.slot.y);
}

// The probe values of a token, as the waveform's 64-bit variables hold them.
template <class Token>
void probe(const Token& t, std::array<int64_t, 3>& o) {
  size_t i = 0;
  for_each_probe_field(t, [&](auto v) { o[i++] = static_cast<int64_t>(v); });
}
// How a waveform shows a probe: its field's own width and signedness (the
// 64-bit variable holding it is traced as that).
struct ProbeFormat {
  int bits = 64;
  bool is_signed = true;
};
template <class Token>
std::array<ProbeFormat, 3> probe_formats() {
  std::array<ProbeFormat, 3> f{};
  size_t i = 0;
  for_each_probe_field(Token{}, [&](auto v) {
    using T = decltype(v);
    f[i++] = {static_cast<int>(8 * sizeof(T)), std::is_signed_v<T>};
  });
  return f;
}

// A register's data field for a waveform: its 64-bit variable and format.
struct NarrowProbe {
  const int64_t& value;
  ProbeFormat format;
};

}  // namespace arp::stage
