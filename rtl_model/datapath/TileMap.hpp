// Which 32 x 32 tiles of each cube face one display memory has storage for
// (memory.tiles): a tile-sparse display memory holds only those tiles and a
// tile table per face, and a texel the host draws on a tile it does not hold
// is lost, as on a face it does not hold. `arpsim plan` writes the tiles a
// scene's motion can draw on.
//
// Text form (one string per memory): the face size S it was listed for and a
// colon, then six fields separated by '/', the faces +X -X +Y -Y +Z -Z; a field
// is "*" (every tile), "-" (no tile) or the face's tiles as hexadecimal digits
// -- tile k = ty x T + tx (T tiles a row, the last one partial when S is no
// multiple of 32) is bit k % 4 of digit k / 4, so there are ceil(T^2 / 4)
// digits and the bits past T^2 are 0. ("641:*/-/-/-/-/-": faces of 641
// texels, every tile of +X, nothing else.) The face size is part of the text
// so that a list never silently covers other texels after memory.face_size
// changes (641 and 660 both have 21 x 21 tiles).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace arp::dp {

struct MemoryConfig;

class TileMap {
 public:
  static constexpr int kFaces = 6;
  TileMap() = default;  // no face size: holds every tile of every face
  // Every tile (`every`) or none, on faces of face_size x face_size texels.
  TileMap(int face_size, bool every);
  // The map a text describes, for faces of face_size texels; false with the reason in `why` (naming the
  // field and face) when it is malformed or was listed for another face size.
  static bool parse(const std::string& text, int face_size, TileMap& out, std::string& why);
  std::string text() const;  // what parse() reads back as this map

  int tiles_per_row() const { return tiles_per_row_; }
  // Whether the memory holds tile (tx, ty) of `face` (tx, ty < tiles_per_row()).
  bool has(int face, int tx, int ty) const {
    if (tiles_per_row_ == 0) return true;
    return bits_[static_cast<size_t>(face)][static_cast<size_t>(ty * tiles_per_row_ + tx)] != 0;
  }
  void set(int face, int tx, int ty, bool held);
  bool every_tile() const;        // whether it holds every tile of every face (nothing is left out)
  bool every_tile(int face) const;
  // Whether it holds every tile of the faces `present` marks (memory.faces): a memory with whole faces.
  bool every_tile(const std::array<bool, kFaces>& present) const;
  int64_t tiles(int face) const;  // tiles held on one face (a map with a face size)
  int64_t tiles() const;          // on all six

 private:
  int face_size_ = 0;
  int tiles_per_row_ = 0;  // 0: every tile of any face size
  std::array<std::vector<uint8_t>, kFaces> bits_;  // per face, row-major by tile: 1 held
};

// Every memory's map (memory.tiles; none listed: every tile of each), or false with the reason ("memory 1: face +Y
// (field 3) has ...") when the list does not fit the memories.
bool tile_maps(const MemoryConfig& m, std::vector<TileMap>& out, std::string& why);

}  // namespace arp::dp
