#include "TileMap.hpp"

#include <stdexcept>

#include "ArpConfig.hpp"
#include "CubeFaceAddressGenerator.hpp"
#include "DisplayMemoryBank.hpp"

namespace arp::dp {

namespace {
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

TileMap::TileMap(int face_size, bool every) : face_size_(face_size), tiles_per_row_(DisplayMemoryBank::tiles_per_row_of(face_size)) {
  if (face_size < 1) throw std::invalid_argument("TileMap: face size " + std::to_string(face_size));
  for (auto& b : bits_) b.assign(static_cast<size_t>(tiles_per_row_) * static_cast<size_t>(tiles_per_row_), every ? 1 : 0);
}

void TileMap::set(int face, int tx, int ty, bool held) {
  if (tiles_per_row_ == 0) throw std::logic_error("TileMap::set on a map without a face size");
  bits_[static_cast<size_t>(face)].at(static_cast<size_t>(ty * tiles_per_row_ + tx)) = held ? 1 : 0;
}

int64_t TileMap::tiles(int face) const {
  if (tiles_per_row_ == 0) throw std::logic_error("TileMap::tiles on a map without a face size");
  int64_t n = 0;
  for (const uint8_t b : bits_[static_cast<size_t>(face)]) n += b;
  return n;
}

int64_t TileMap::tiles() const {
  int64_t n = 0;
  for (int f = 0; f < kFaces; ++f) n += tiles(f);
  return n;
}

bool TileMap::every_tile(int face) const {
  return tiles_per_row_ == 0 || tiles(face) == int64_t{tiles_per_row_} * tiles_per_row_;
}

bool TileMap::every_tile(const std::array<bool, kFaces>& present) const {
  for (int f = 0; f < kFaces; ++f)
    if (present[static_cast<size_t>(f)] && !every_tile(f)) return false;
  return true;
}

bool TileMap::every_tile() const {
  for (int f = 0; f < kFaces; ++f)
    if (!every_tile(f)) return false;
  return true;
}

bool TileMap::parse(const std::string& text, int face_size, TileMap& out, std::string& why) {
  TileMap m(face_size, false);
  const size_t colon = text.find(':');
  const std::string size_text = colon == std::string::npos ? std::string() : text.substr(0, colon);
  if (size_text.empty() || size_text.size() > 6 || size_text.find_first_not_of("0123456789") != std::string::npos) {
    why = "must begin with the face size it was listed for and a colon (\"" + std::to_string(face_size) + ":\")";
    return false;
  }
  if (std::stoi(size_text) != face_size) {
    why = "was listed for faces of " + size_text + " texels; memory.face_size is " + std::to_string(face_size);
    return false;
  }
  const size_t per_face = static_cast<size_t>(m.tiles_per_row_) * static_cast<size_t>(m.tiles_per_row_);
  const size_t digits = (per_face + 3) / 4;
  size_t pos = colon + 1;
  for (int f = 0; f < kFaces; ++f) {
    const size_t end = text.find('/', pos);
    if ((end == std::string::npos) != (f == kFaces - 1)) {
      why = (end == std::string::npos ? "has " + std::to_string(f + 1) + " fields" : std::string("has more than six fields")) +
            " separated by '/': one for each face +X -X +Y -Y +Z -Z";
      return false;
    }
    const std::string field = text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    const std::string where = "face " + std::string(face_name(f)) + " (field " + std::to_string(f + 1) + ")";
    auto& bits = m.bits_[static_cast<size_t>(f)];
    if (field == "*") {
      bits.assign(per_face, 1);
    } else if (field != "-") {
      if (field.size() != digits) {
        why = where + " has " + std::to_string(field.size()) + " characters: \"*\" (every tile), \"-\" (none) or " +
              std::to_string(digits) + " hexadecimal digits, a bit for each of the " + std::to_string(m.tiles_per_row_) + " x " +
              std::to_string(m.tiles_per_row_) + " tiles of a face of " + std::to_string(face_size) + " texels";
        return false;
      }
      for (size_t d = 0; d < digits; ++d) {
        const int v = hex_value(field[d]);
        if (v < 0) {
          why = where + " has '" + std::string(1, field[d]) + "' at character " + std::to_string(d) + ": hexadecimal digits only";
          return false;
        }
        for (size_t b = 0; b < 4; ++b) {
          const size_t k = d * 4 + b;
          const bool on = ((v >> b) & 1) != 0;
          if (k < per_face) bits[k] = on ? 1 : 0;
          else if (on) {
            why = where + "'s last digit sets bit " + std::to_string(k) + ", past the face's " + std::to_string(per_face) + " tiles";
            return false;
          }
        }
      }
    }
    pos = end == std::string::npos ? text.size() : end + 1;
  }
  out = std::move(m);
  return true;
}

std::string TileMap::text() const {
  if (tiles_per_row_ == 0) throw std::logic_error("TileMap::text of a map without a face size");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s = std::to_string(face_size_) + ":";
  for (int f = 0; f < kFaces; ++f) {
    if (f) s += '/';
    const auto& bits = bits_[static_cast<size_t>(f)];
    const int64_t n = tiles(f);
    if (n == 0) s += '-';
    else if (n == static_cast<int64_t>(bits.size())) s += '*';
    else
      for (size_t d = 0; d * 4 < bits.size(); ++d) {
        int v = 0;
        for (size_t b = 0; b < 4 && d * 4 + b < bits.size(); ++b) v |= bits[d * 4 + b] << b;
        s += kHex[v];
      }
  }
  return s;
}

bool tile_maps(const MemoryConfig& m, std::vector<TileMap>& out, std::string& why) {
  out.assign(static_cast<size_t>(m.count), TileMap());
  if (m.tiles.empty()) return true;
  if (static_cast<int>(m.tiles.size()) != m.count) {
    why = "has " + std::to_string(m.tiles.size()) + " strings and memory.count is " + std::to_string(m.count) +
          ": one for each memory, or none (every tile)";
    return false;
  }
  for (size_t k = 0; k < m.tiles.size(); ++k)
    if (!TileMap::parse(m.tiles[k], m.face_size, out[k], why)) {
      why = "memory " + std::to_string(k) + ": " + why;
      return false;
    }
  return true;
}

}  // namespace arp::dp
