// Bit fields of Verilator's port types (CData, SData, IData, QData and
// VlWide for ports wider than 64 bits), so that a port's packed fields are
// read and written the same way whatever width a configuration gives it.
// Fields are at most 64 bits wide.
#pragma once
#include <cstdint>
#include <type_traits>

#include <verilated.h>

namespace arp::vl {

inline uint64_t low_mask(int width) { return width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1; }

template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
void put_field(T& s, int lsb, int width, int64_t v) {
  const uint64_t mask = low_mask(width) << lsb;
  s = static_cast<T>((static_cast<uint64_t>(s) & ~mask) | ((static_cast<uint64_t>(v) << lsb) & mask));
}
template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
uint64_t get_unsigned(const T& s, int lsb, int width) {
  return (static_cast<uint64_t>(s) >> lsb) & low_mask(width);
}

// Wide ports: the field in pieces, one per 32-bit word it touches.
template <std::size_t N>
void put_field(VlWide<N>& s, int lsb, int width, int64_t v) {
  uint64_t bits = static_cast<uint64_t>(v) & low_mask(width);
  while (width > 0) {
    const int at = lsb % 32, n = width < 32 - at ? width : 32 - at;
    const uint32_t m = static_cast<uint32_t>(low_mask(n) << at);
    auto& w = s.at(static_cast<size_t>(lsb / 32));
    w = (w & ~m) | (static_cast<uint32_t>(bits << at) & m);
    bits >>= n;
    lsb += n;
    width -= n;
  }
}
template <std::size_t N>
uint64_t get_unsigned(const VlWide<N>& s, int lsb, int width) {
  uint64_t v = 0;
  int done = 0;
  while (done < width) {
    const int at = lsb % 32, n = width - done < 32 - at ? width - done : 32 - at;
    v |= ((static_cast<uint64_t>(s.at(static_cast<size_t>(lsb / 32))) >> at) & low_mask(n)) << done;
    lsb += n;
    done += n;
  }
  return v;
}

template <class T>
int64_t get_signed(const T& s, int lsb, int width) {
  const uint64_t sign = uint64_t{1} << (width - 1);
  return static_cast<int64_t>((get_unsigned(s, lsb, width) ^ sign) - sign);
}

// Vector ports: three signed fields of `width` bits each, x in the low bits
// (V: any type with members x, y, z, e.g. dp::Vec3q).
template <class T, class V>
void put_vector(T& s, int width, const V& v) {
  put_field(s, 0, width, v.x);
  put_field(s, width, width, v.y);
  put_field(s, 2 * width, width, v.z);
}
template <class V, class T>
V get_vector(const T& s, int width) {
  using C = decltype(V{}.x);
  return {static_cast<C>(get_signed(s, 0, width)), static_cast<C>(get_signed(s, width, width)),
          static_cast<C>(get_signed(s, 2 * width, width))};
}

}  // namespace arp::vl
