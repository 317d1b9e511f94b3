#include <gtest/gtest.h>

#include <array>
#include <random>
#include <thread>
#include <vector>

#include <stdexcept>

#include "rtl_model/datapath/DisplayMemoryBank.hpp"

using namespace arp::dp;

TEST(DisplayMemoryBank, StorageIsSparse) {
  DisplayMemoryBank b{MemoryFormat{}};
  EXPECT_EQ(b.bytes_allocated(), 0u);  // nothing written, nothing stored
  EXPECT_EQ(b.read(3, 100, 200), MemoryFormat{}.empty_word());
  b.write(2, 40, 70, 0x123456, 1000);
  EXPECT_EQ(b.tiles_allocated(), 1u);
  b.write(2, 41, 71, 0x654321, 1000);  // same 32x32 tile
  EXPECT_EQ(b.tiles_allocated(), 1u);
  b.write(2, 500, 500, 1, 1);
  EXPECT_EQ(b.tiles_allocated(), 2u);
  // One face's tile table (16x16 tile numbers) plus the pool: the empty tile
  // and two 8 KiB tiles (growth may have reserved one more).
  const size_t tile = DisplayMemoryBank::kTileWords * 8;  // 33 x 33 words: texels and apron
  EXPECT_GE(b.bytes_allocated(), 3 * tile + 256 * sizeof(int32_t));
  EXPECT_LE(b.bytes_allocated(), 4 * tile + 256 * sizeof(int32_t));
  DisplayMemorySet set(MemoryConfig{}, 2);
  EXPECT_EQ(set.bytes_allocated(), 0u);  // 8 banks, 2 x 6 faces each, all free
}

// A face the configuration leaves out (memory.faces) has no storage: what the host writes there is lost
// and counted, texel by texel or a face at a time, and the face reads empty; the others are untouched.
TEST(DisplayMemoryBank, AnAbsentFaceStoresNothingAndCountsWhatIsLost) {
  MemoryConfig m;
  m.face_size = 64;
  m.faces = {1, 1, 0, 1, 1, 1};  // no +Y
  DisplayMemoryBank b{MemoryFormat(m)};
  b.write(2, 5, 5, 0x123456, 7);
  std::vector<uint64_t> face(64 * 64, b.format().empty_word());
  face[100] = face[2000] = (uint64_t{9} << 32) | 0xABCDEF;
  EXPECT_EQ(b.write_face(2, face.data(), b.format().empty_word()), 0);
  EXPECT_EQ(b.writes_lost(), 3);
  EXPECT_EQ(b.tiles_allocated(), 0u);
  EXPECT_EQ(b.write_face(3, face.data(), b.format().empty_word()), 2);
  b.commit();
  b.vblank();
  EXPECT_EQ(b.read(2, 5, 5), b.format().empty_word());
  EXPECT_EQ(b.read(2, 100 % 64, 100 / 64), b.format().empty_word());
  EXPECT_EQ(b.read(3, 100 % 64, 100 / 64), face[100]);
  EXPECT_EQ(b.writes_lost(), 3);
}

TEST(DisplayMemoryBank, AFullCubeCostsLittleMoreThanItsTiles) {
  DisplayMemoryBank b{MemoryFormat{}};
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < 512; y += 32)
      for (int x = 0; x < 512; x += 32) b.write(f, x, y, 1, 1);
  const size_t tiles = 6 * 256;
  EXPECT_EQ(b.tiles_allocated(), tiles);
  const size_t tile = DisplayMemoryBank::kTileWords * 8;
  const size_t data = (tiles + 1) * tile;
  EXPECT_GE(b.bytes_allocated(), data);
  EXPECT_LE(b.bytes_allocated(), data * 5 / 4 + 6 * 256 * 4 + tile);  // growth slack <= a quarter
}

// Tiles in table order: a whole cube written face by face, row by row, leaves every tile where the table
// order puts it (the functional model then reads without the table); a face left partly unwritten, a
// face written out of order, or nothing written does not.
TEST(DisplayMemoryBank, TilesInTableOrderOnlyWhenAWholeCubeIsWrittenInOrder) {
  MemoryConfig mc;
  mc.face_size = 70;  // not a multiple of the tile: the last tile of a row is part-filled
  const MemoryFormat fmt(mc);
  auto cube = [&](bool skip_last_tile, bool face_order_reversed) {
    DisplayMemoryBank b(fmt);
    for (int i = 0; i < 6; ++i) {
      const int f = face_order_reversed ? 5 - i : i;
      for (int y = 0; y < 70; ++y)
        for (int x = 0; x < 70; ++x)
          if (!(skip_last_tile && f == 5 && x >= 64 && y >= 64)) b.write(f, x, y, fmt.pack_rgb8(x, y, f), 7);
    }
    b.commit();
    b.vblank();
    return b.front_tiles_in_order();
  };
  EXPECT_TRUE(cube(false, false));
  EXPECT_FALSE(cube(true, false));
  EXPECT_FALSE(cube(false, true));
  DisplayMemoryBank empty(fmt);
  EXPECT_FALSE(empty.front_tiles_in_order());
}

TEST(DisplayMemoryBank, DoubleBufferSwapsOnlyAtVblankAfterCommit) {
  DisplayMemoryBank b{MemoryFormat{}};
  b.write(0, 1, 2, 0xABCDEF, 77);
  EXPECT_EQ(b.read(0, 1, 2), MemoryFormat{}.empty_word());  // host writes the back buffer
  EXPECT_EQ(texel_color(b.read_back(0, 1, 2)), 0xABCDEFu);
  EXPECT_FALSE(b.vblank());  // not committed: no swap
  EXPECT_EQ(b.read(0, 1, 2), MemoryFormat{}.empty_word());
  b.commit();
  EXPECT_EQ(b.read(0, 1, 2), MemoryFormat{}.empty_word());  // committed, still waiting for vblank
  EXPECT_TRUE(b.vblank());
  EXPECT_EQ(texel_color(b.read(0, 1, 2)), 0xABCDEFu);
  EXPECT_EQ(texel_depth(b.read(0, 1, 2)), 77u);
  EXPECT_FALSE(b.vblank());  // one commit, one swap
  EXPECT_TRUE(b.front_face_written(0));
  EXPECT_FALSE(b.front_face_written(1));
  // The old front is now the back; clearing it frees its storage.
  b.clear_back();
  EXPECT_EQ(b.read_back(0, 1, 2), MemoryFormat{}.empty_word());
  EXPECT_EQ(b.tiles_allocated(), 1u);  // only the front buffer's tile remains
  EXPECT_EQ(texel_color(b.read(0, 1, 2)), 0xABCDEFu);
}

TEST(DisplayMemoryBank, WritesOutsideTheCubeOrFormatAreRefused) {
  DisplayMemoryBank b{MemoryFormat{}};
  EXPECT_THROW(b.write(6, 0, 0, 0, 0), std::out_of_range);
  EXPECT_THROW(b.write(0, 512, 0, 0, 0), std::out_of_range);
  EXPECT_THROW(b.write(0, 0, -1, 0, 0), std::out_of_range);
  EXPECT_THROW(b.write(0, 0, 0, 1u << 24, 0), std::out_of_range);  // 25-bit colour into 8:8:8
  EXPECT_THROW(b.write(0, 0, 0, 0, 1u << 16), std::out_of_range);  // 17-bit depth into 16
  EXPECT_EQ(b.tiles_allocated(), 0u);
}

TEST(DisplayMemoryBank, ApronsMirrorTheNeighbouringTilesWhicheverIsWrittenFirst) {
  // Every bilinear quad must find its four taps in the tile of its top-left
  // tap: the apron of tile (tx, ty) holds column 0 of (tx+1, ty), row 0 of
  // (tx, ty+1) and texel (0, 0) of (tx+1, ty+1). Write in two orders.
  for (bool neighbours_first : {false, true}) {
    DisplayMemoryBank b{MemoryFormat{}};
    auto write_neighbours = [&] {
      for (int i = 0; i < 32; ++i) {
        b.write(1, 64, 32 + i, 1000 + i, 7);  // column 0 of tile (2, 1)
        b.write(1, 32 + i, 64, 2000 + i, 7);  // row 0 of tile (1, 2)
      }
      b.write(1, 64, 64, 3000, 7);  // texel (0, 0) of tile (2, 2)
    };
    if (neighbours_first) write_neighbours();
    b.write(1, 40, 40, 5, 5);  // tile (1, 1) itself
    if (!neighbours_first) write_neighbours();
    b.commit();
    b.vblank();
    const int32_t t = b.front_tile_index(1)[1 * b.tiles_per_row() + 1];
    ASSERT_NE(t, 0);
    const uint64_t* tile = b.front_pool() + static_cast<size_t>(t) * DisplayMemoryBank::kTileWords;
    for (int i = 0; i < 32; ++i) {
      EXPECT_EQ(texel_color(tile[DisplayMemoryBank::tile_word(32, i)]), 1000u + i) << neighbours_first;
      EXPECT_EQ(texel_color(tile[DisplayMemoryBank::tile_word(i, 32)]), 2000u + i) << neighbours_first;
    }
    EXPECT_EQ(texel_color(tile[DisplayMemoryBank::tile_word(32, 32)]), 3000u);
    EXPECT_EQ(texel_color(b.read(1, 40, 40)), 5u);
  }
}

namespace {
// Commits and swaps both banks, then compares every stored word of these faces, aprons included, tile by
// tile (which tiles exist, and their words; the tile numbers themselves may differ).
void expect_same_tiles(DisplayMemoryBank& a, DisplayMemoryBank& b, std::initializer_list<int> faces) {
  for (DisplayMemoryBank* bank : {&a, &b}) {
    bank->commit();
    bank->vblank();
  }
  for (int f : faces)
    for (int t = 0; t < b.tiles_per_row() * b.tiles_per_row(); ++t) {
      const int32_t ta = a.front_tile_index(f)[t], tb = b.front_tile_index(f)[t];
      ASSERT_EQ(ta == 0, tb == 0) << "face " << f << " tile " << t;
      const uint64_t* pa = a.front_pool() + static_cast<size_t>(ta) * DisplayMemoryBank::kTileWords;
      const uint64_t* pb = b.front_pool() + static_cast<size_t>(tb) * DisplayMemoryBank::kTileWords;
      for (int k = 0; k < DisplayMemoryBank::kTileWords; ++k) ASSERT_EQ(pa[k], pb[k]) << "face " << f << " tile " << t << " word " << k;
    }
}
// A sparse face of random texels (S^2 words, the rest empty), a 10 x 10 patch across the corner of four
// tiles at (60, 60), and texel (32, 32) alone: a tile's (0, 0) only.
std::vector<uint64_t> sparse_face(const MemoryFormat& fmt, unsigned seed) {
  const int S = fmt.face_size;
  std::mt19937 rng(seed);
  std::vector<uint64_t> words(static_cast<size_t>(S) * static_cast<size_t>(S), fmt.empty_word());
  for (int i = 0; i < 300; ++i) {
    const int x = static_cast<int>(rng() % static_cast<unsigned>(S)), y = static_cast<int>(rng() % static_cast<unsigned>(S));
    words[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)] = (uint64_t{rng() % 60000u} << 32) | (rng() & 0xFFFFFFu);
  }
  for (int y = 60; y < 70; ++y)
    for (int x = 60; x < 70; ++x) words[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)] = (uint64_t{9} << 32) | 0x10203;
  words[static_cast<size_t>(32) * static_cast<size_t>(S) + 32] = (uint64_t{4} << 32) | 7;
  return words;
}
}  // namespace

// write_face against write(): sparse random faces (isolated texels, tile borders, a patch across a corner)
// over a buffer already holding texels, at a face size that is and one that is not a multiple of the tile.
// Every stored word, aprons included, and the tile count must agree.
TEST(DisplayMemoryBank, AWholeFaceIsWrittenAsTexelByTexel) {
  for (int S : {128, 100}) {
    MemoryConfig mc;
    mc.face_size = S;
    const MemoryFormat fmt(mc);
    DisplayMemoryBank by_texel(fmt), by_face(fmt);
    const std::vector<uint64_t> words = sparse_face(fmt, static_cast<unsigned>(S));
    for (DisplayMemoryBank* b : {&by_texel, &by_face}) {
      b->write(3, 5, 5, 0x111111, 100);  // already there: another face, and this face
      b->write(2, 31, 31, 0x222222, 200);
    }
    int64_t n = 0;
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        const uint64_t w = words[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)];
        if (w == fmt.empty_word()) continue;
        by_texel.write(2, x, y, texel_color(w), texel_depth(w));
        ++n;
      }
    EXPECT_EQ(by_face.write_face(2, words.data(), fmt.empty_word()), n);
    EXPECT_EQ(by_face.tiles_allocated(), by_texel.tiles_allocated()) << S;
    expect_same_tiles(by_texel, by_face, {2, 3});
  }
  DisplayMemoryBank b{MemoryFormat{}};
  std::vector<uint64_t> wide(512 * 512, MemoryFormat{}.empty_word());
  wide[7] = uint64_t{1} << 24;  // a 25-bit colour
  EXPECT_THROW(b.write_face(0, wide.data(), MemoryFormat{}.empty_word()), std::out_of_range);
  EXPECT_THROW(b.write_face(6, wide.data(), MemoryFormat{}.empty_word()), std::out_of_range);
}

// Several faces reserved at once and copied from two threads (the host renderer's store) against write()
// texel by texel: every stored word, aprons included. The pool grows once, exactly: its capacity is the
// tiles written plus the empty tile. A face left out of the reservation cannot be stored.
TEST(DisplayMemoryBank, FacesReservedTogetherAndStoredConcurrentlyAreWrittenAsTexelByTexel) {
  const int S = 100;  // not a multiple of the tile
  MemoryConfig mc;
  mc.face_size = S;
  const MemoryFormat fmt(mc);
  const size_t n = static_cast<size_t>(S) * static_cast<size_t>(S);
  std::mt19937 rng(7);
  std::array<std::vector<uint64_t>, 6> words;
  std::array<const uint64_t*, 6> given{};
  DisplayMemoryBank by_texel(fmt), by_faces(fmt);
  for (int f : {0, 2, 3, 5}) {  // faces 1 and 4 not drawn
    auto& w = words[static_cast<size_t>(f)];
    w.assign(n, fmt.empty_word());
    const int filled = f == 0 ? static_cast<int>(n) : 400 * f;  // one face full, the others sparse
    for (int i = 0; i < filled; ++i) {
      const size_t k = f == 0 ? static_cast<size_t>(i) : rng() % n;
      w[k] = (uint64_t{rng() % 60000u} << 32) | (rng() & 0xFFFFFFu);
    }
    given[static_cast<size_t>(f)] = w.data();
    for (size_t k = 0; k < n; ++k)
      if (w[k] != fmt.empty_word())
        by_texel.write(f, static_cast<int>(k % static_cast<size_t>(S)), static_cast<int>(k / static_cast<size_t>(S)), texel_color(w[k]),
                       texel_depth(w[k]));
  }
  int64_t expected = 0;
  for (const auto& w : words)
    for (uint64_t x : w) expected += x != fmt.empty_word();
  ASSERT_EQ(by_faces.reserve_faces(given, fmt.empty_word()), expected);
  EXPECT_EQ(by_faces.tiles_allocated(), by_texel.tiles_allocated());
  const size_t tables = 4 * static_cast<size_t>(by_faces.tiles_per_row() * by_faces.tiles_per_row()) * sizeof(int32_t);
  EXPECT_EQ(by_faces.bytes_allocated(), (by_texel.tiles_allocated() + 1) * DisplayMemoryBank::kTileWords * sizeof(uint64_t) + tables);
  std::thread a([&] { for (int f : {0, 3}) by_faces.store_face(f, given[static_cast<size_t>(f)], fmt.empty_word()); });
  std::thread b([&] { for (int f : {2, 5}) by_faces.store_face(f, given[static_cast<size_t>(f)], fmt.empty_word()); });
  a.join();
  b.join();
  // A face the format leaves out: its words are checked and counted as lost, nothing stored.
  MemoryConfig without = mc;
  without.faces[3] = 0;
  DisplayMemoryBank partial{MemoryFormat(without)};
  int64_t on_three = 0;
  for (uint64_t x : words[3]) on_three += x != fmt.empty_word();
  EXPECT_EQ(partial.reserve_faces(given, fmt.empty_word()), expected - on_three);
  EXPECT_EQ(partial.writes_lost(), on_three);
  std::vector<uint64_t> stray(n, fmt.empty_word());
  stray[5] = 1;
  EXPECT_THROW(by_faces.store_face(1, stray.data(), fmt.empty_word()), std::logic_error);  // face 1 was not reserved
  expect_same_tiles(by_texel, by_faces, {0, 1, 2, 3, 4, 5});
}

TEST(DisplayMemoryBank, FaceSizesThatAreNotMultiplesOfTheTile) {
  MemoryFormat f;
  f.face_size = 37;
  DisplayMemoryBank b{f};
  EXPECT_EQ(b.tiles_per_row(), 2);
  b.write(5, 36, 36, 9, 9);
  b.commit();
  b.vblank();
  EXPECT_EQ(texel_color(b.read(5, 36, 36)), 9u);
  EXPECT_EQ(b.read(5, 35, 36), f.empty_word());
}

// The tiles drawn on are those whose own texels were written, ever, texel by texel or a face at a time:
// not a tile allocated only for its apron (a texel on its right neighbour's left column), and not undone by
// clearing the back buffer.
TEST(DisplayMemoryBank, TheTilesDrawnOnAreThoseWhoseOwnTexelsWereWritten) {
  MemoryFormat f;
  f.face_size = 100;  // 4 tiles a row, the last 4 texels wide
  for (const bool whole_face : {false, true}) {
    DisplayMemoryBank b{f};
    const std::vector<std::array<int, 2>> texels{{32, 0}, {99, 99}, {64, 64}};
    std::vector<uint64_t> face(100 * 100, ~uint64_t{0});
    for (const auto& [x, y] : texels) {
      if (whole_face) face[static_cast<size_t>(y * 100 + x)] = (uint64_t{5} << 32) | 7;
      else b.write(1, x, y, 7, 5);
    }
    if (whole_face) b.write_face(1, face.data(), ~uint64_t{0});
    // Allocated: (1,0) and its left neighbour (0,0) for the apron; (3,3); (2,2) with (1,2), (2,1), (1,1).
    EXPECT_EQ(b.tiles_allocated(), 7u) << whole_face;
    EXPECT_EQ(b.tiles_ever_written(), 3) << whole_face;
    EXPECT_TRUE(b.tile_ever_written(1, 1, 0));
    EXPECT_FALSE(b.tile_ever_written(1, 0, 0));
    EXPECT_TRUE(b.tile_ever_written(1, 3, 3));
    EXPECT_TRUE(b.tile_ever_written(1, 2, 2));
    EXPECT_FALSE(b.tile_ever_written(1, 1, 1));
    EXPECT_FALSE(b.tile_ever_written(0, 1, 0));  // another face
    b.clear_back();
    EXPECT_EQ(b.tiles_allocated(), 0u);
    EXPECT_EQ(b.tiles_ever_written(), 3);
  }
}

// The most tiles in use at once -- own texels written, the two buffers together -- is what a tile pool both
// buffers share would need: an image of 3 tiles shown while the next, of 4 (one the same tile), is drawn
// needs 7 slots; a buffer cleared frees its tiles; a tile allocated only for its apron takes none; a texel
// written twice, or a tile written again in the same buffer, counts once. Texel by texel and a face at a time.
TEST(DisplayMemoryBank, TheMostTilesAtOnceAreBothBuffersOwnTiles) {
  MemoryFormat f;
  f.face_size = 100;  // 4 tiles a row
  for (const bool whole_face : {false, true}) {
    DisplayMemoryBank b{f};
    auto draw = [&](const std::vector<std::array<int, 3>>& texels) {  // (face, x, y)
      if (!whole_face) {
        for (const auto& [fc, x, y] : texels) b.write(fc, x, y, 7, 5);
        return;
      }
      std::array<std::vector<uint64_t>, 6> faces;
      for (auto& w : faces) w.assign(100 * 100, ~uint64_t{0});
      for (const auto& [fc, x, y] : texels) faces[static_cast<size_t>(fc)][static_cast<size_t>(y * 100 + x)] = (uint64_t{5} << 32) | 7;
      for (int fc = 0; fc < 6; ++fc) b.write_face(fc, faces[static_cast<size_t>(fc)].data(), ~uint64_t{0});
    };
    // Image 1: tiles (1,0) of face 1 (its left neighbour (0,0) allocated for the apron only), (3,3) of face 1 and
    // (0,0) of face 4.
    draw({{1, 32, 0}, {1, 99, 99}, {1, 98, 99}, {4, 5, 5}});
    EXPECT_EQ(b.tiles_most_at_once(), 3) << whole_face;
    b.commit();
    b.vblank();
    // Image 2 in the other buffer: (1,0) of face 1 again, (2,2) of face 1 (with its three apron neighbours),
    // (0,0) of faces 2 and 3.
    b.clear_back();
    draw({{1, 40, 10}, {1, 64, 64}, {2, 0, 0}, {3, 31, 31}});
    EXPECT_EQ(b.tiles_most_at_once(), 7) << whole_face;
    draw({{1, 41, 11}, {2, 1, 1}});  // tiles this buffer has
    EXPECT_EQ(b.tiles_most_at_once(), 7) << whole_face;
    b.commit();
    b.vblank();
    // Image 3 where image 1 was: cleared first, so 4 + 1 at most.
    b.clear_back();
    draw({{5, 50, 50}});
    EXPECT_EQ(b.tiles_most_at_once(), 7) << whole_face;
    EXPECT_EQ(b.tiles_ever_written(), 3 + 3 + 1) << whole_face;
    // Without clearing, a buffer keeps its tiles: image 4 over image 2's 4 tiles, 1 new: 1 + 5.
    b.commit();
    b.vblank();
    draw({{0, 0, 0}});
    EXPECT_EQ(b.tiles_most_at_once(), 7) << whole_face;
    draw({{0, 40, 0}, {0, 80, 0}});
    EXPECT_EQ(b.tiles_most_at_once(), 8) << whole_face;
  }
  // A tile the back buffer holds only for its apron, drawn on in the other buffer before, then drawn on here: its
  // own texels are this buffer's too (1 shown, 2 drawn).
  for (const bool whole_face : {false, true}) {
    DisplayMemoryBank b{f};
    auto draw = [&](int x, int y) {
      if (!whole_face) return void(b.write(1, x, y, 7, 5));
      std::vector<uint64_t> w(100 * 100, ~uint64_t{0});
      w[static_cast<size_t>(y * 100 + x)] = (uint64_t{5} << 32) | 7;
      b.write_face(1, w.data(), ~uint64_t{0});
    };
    draw(40, 40);  // tile (1,1)
    b.commit();
    b.vblank();
    b.clear_back();
    draw(64, 64);  // tile (2,2), and (1,1) for its apron
    EXPECT_EQ(b.tiles_most_at_once(), 2) << whole_face;
    draw(40, 40);
    EXPECT_EQ(b.tiles_most_at_once(), 3) << whole_face;
  }
}

// A bank holding only some tiles (memory.tiles) stores what a bank holding every tile stores when the texels
// on the tiles it does not hold are never drawn: the same tiles and words, aprons included (a held tile's
// apron does not copy a neighbour it does not hold), written a face at a time or texel by texel. The texels
// on those tiles are lost and counted. Held: a checkerboard of face 2's tiles, so every held tile's right
// and bottom neighbours are not held and its bottom-right one is.
TEST(DisplayMemoryBank, ATileItDoesNotHoldIsLostAsIfNeverDrawn) {
  for (const int S : {128, 100}) {
    MemoryConfig mc;
    mc.face_size = S;
    const MemoryFormat fmt(mc);
    TileMap map(S, true);
    const int T = map.tiles_per_row();
    for (int ty = 0; ty < T; ++ty)
      for (int tx = 0; tx < T; ++tx) map.set(2, tx, ty, (tx + ty) % 2 == 1);
    const std::vector<uint64_t> words = sparse_face(fmt, static_cast<unsigned>(S) + 1);
    std::vector<uint64_t> kept = words;  // what a bank holding every tile is given instead
    int64_t off = 0, on = 0;
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        uint64_t& w = kept[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)];
        if (w == fmt.empty_word()) continue;
        if ((x / 32 + y / 32) % 2 == 0) {
          w = fmt.empty_word();
          ++off;
        } else {
          ++on;
        }
      }
    ASSERT_GT(off, 0);
    DisplayMemoryBank by_face(fmt, map), by_texel(fmt, map), whole(fmt), whole_too(fmt);
    EXPECT_EQ(by_face.write_face(2, words.data(), fmt.empty_word()), on);
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x)
        if (const uint64_t w = words[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)]; w != fmt.empty_word())
          by_texel.write(2, x, y, texel_color(w), texel_depth(w));
    for (DisplayMemoryBank* b : {&whole, &whole_too}) b->write_face(2, kept.data(), fmt.empty_word());
    for (DisplayMemoryBank* b : {&by_face, &by_texel}) {
      EXPECT_EQ(b->writes_lost_off_tiles(), off) << S;
      EXPECT_EQ(b->texels_written(), on) << S;
      EXPECT_EQ(b->writes_lost(), 0);
      EXPECT_EQ(b->tiles_ever_written(), whole.tiles_ever_written()) << S;
      EXPECT_EQ(b->tiles_allocated(), whole.tiles_allocated()) << S;
    }
    expect_same_tiles(by_face, whole, {2});
    expect_same_tiles(by_texel, whole_too, {2});
    EXPECT_EQ(by_face.read(2, 5, 5), fmt.empty_word());  // tile (0, 0): not held
    // Held tile (1, 0) drawn on only through its apron, from its right neighbour (2, 0) and the one below,
    // (1, 1), neither held: nothing is allocated.
    std::vector<uint64_t> apron_only(static_cast<size_t>(S) * static_cast<size_t>(S), fmt.empty_word());
    apron_only[5 * static_cast<size_t>(S) + 64] = (uint64_t{3} << 32) | 1;
    apron_only[32 * static_cast<size_t>(S) + 40] = (uint64_t{3} << 32) | 2;
    DisplayMemoryBank edges(fmt, map);
    EXPECT_EQ(edges.write_face(2, apron_only.data(), fmt.empty_word()), 0);
    EXPECT_EQ(edges.writes_lost_off_tiles(), 2);
    EXPECT_EQ(edges.tiles_allocated(), 0u) << S;
    // Texel (64, 32), tile (2, 1)'s first, held: it is the bottom-right corner of held tile (1, 0)'s apron, which
    // is allocated for it and keeps it, as a bank holding every tile does (tiles (2, 0) and (1, 1), not held,
    // carry it in their aprons too).
    std::vector<uint64_t> corner(static_cast<size_t>(S) * static_cast<size_t>(S), fmt.empty_word());
    corner[32 * static_cast<size_t>(S) + 64] = (uint64_t{5} << 32) | 3;
    DisplayMemoryBank held_corner(fmt, map), every_corner(fmt);
    for (DisplayMemoryBank* b : {&held_corner, &every_corner}) EXPECT_EQ(b->write_face(2, corner.data(), fmt.empty_word()), 1);
    EXPECT_EQ(held_corner.tiles_allocated(), 4u);
    expect_same_tiles(held_corner, every_corner, {2});
    const int32_t t10 = held_corner.front_tile_index(2)[1];
    ASSERT_NE(t10, 0);
    EXPECT_EQ(held_corner.front_pool()[static_cast<size_t>(t10) * DisplayMemoryBank::kTileWords + DisplayMemoryBank::tile_word(32, 32)],
              corner[32 * static_cast<size_t>(S) + 64]);
  }
  // A face memory.faces leaves out loses its texels as an absent face (writes_lost), whatever the tiles say.
  MemoryConfig mc;
  mc.faces = {1, 1, 1, 1, 1, 0};
  TileMap map(mc.face_size, true);
  map.set(0, 0, 0, false);
  DisplayMemoryBank b(MemoryFormat(mc), map);
  b.write(5, 3, 3, 1, 1);
  b.write(0, 3, 3, 1, 1);
  EXPECT_EQ(b.writes_lost(), 1);
  EXPECT_EQ(b.writes_lost_off_tiles(), 1);
  EXPECT_EQ(b.texels_written(), 0);
}

// A tile pool (memory.tile_pool) of P slots, both buffers together: the first P tiles whose own texels are drawn
// get a slot, in the order they are first drawn on (write_face: tiles row-major; write(): the texels' order),
// and every later one is lost as a tile the bank does not hold is -- the same tiles and words, aprons included,
// as a bank whose tile map holds exactly the tiles given a slot, and its texels counted as lost for the pool.
// A cleared buffer frees its slots; the one shown keeps its own.
TEST(DisplayMemoryBank, ATileThePoolHasNoSlotForIsLostAsATileNotHeld) {
  for (const int S : {128, 100}) {
    MemoryConfig mc;
    mc.face_size = S;
    const MemoryFormat fmt(mc);
    const std::vector<uint64_t> words = sparse_face(fmt, static_cast<unsigned>(S) + 7);
    const int T = DisplayMemoryBank::tiles_per_row_of(S);
    constexpr int64_t P = 5;
    auto at = [&](int x, int y) { return words[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)]; };
    // The tiles given a slot, worked out here: first come, first served, in each path's order.
    TileMap by_tile_order(S, false), by_texel_order(S, false);
    std::vector<int64_t> own_texels;  // of each tile drawn on, row-major
    for (int ty = 0; ty < T; ++ty)
      for (int tx = 0; tx < T; ++tx) {
        int64_t own = 0;
        for (int y = ty * 32; y < std::min(S, ty * 32 + 32); ++y)
          for (int x = tx * 32; x < std::min(S, tx * 32 + 32); ++x) own += at(x, y) != fmt.empty_word();
        if (own == 0) continue;
        if (own_texels.size() < static_cast<size_t>(P)) by_tile_order.set(2, tx, ty, true);
        own_texels.push_back(own);
      }
    auto lost_beyond = [&](int64_t n) {  // the texels of the tiles after the first n
      int64_t t = 0;
      for (size_t i = static_cast<size_t>(n); i < own_texels.size(); ++i) t += own_texels[i];
      return t;
    };
    ASSERT_GT(own_texels.size(), static_cast<size_t>(2 * P));
    const int64_t lost_tile_order = lost_beyond(P), all = lost_beyond(0);
    int64_t slotted = 0, lost_texel_order = 0;
    std::vector<int> seen(static_cast<size_t>(T * T), 0);  // 1: slotted, 2: refused
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        if (at(x, y) == fmt.empty_word()) continue;
        int& k = seen[static_cast<size_t>((y / 32) * T + x / 32)];
        if (k == 0) k = slotted < P ? 1 : 2;
        if (k == 1 && !by_texel_order.has(2, x / 32, y / 32)) {
          by_texel_order.set(2, x / 32, y / 32, true);
          ++slotted;
        }
        lost_texel_order += k == 2;
      }
    // The face path.
    DisplayMemoryBank pooled(fmt, {}, P), mapped(fmt, by_tile_order);
    EXPECT_EQ(pooled.write_face(2, words.data(), fmt.empty_word()), mapped.write_face(2, words.data(), fmt.empty_word())) << S;
    EXPECT_EQ(pooled.writes_lost_pool_full(), lost_tile_order) << S;
    EXPECT_EQ(mapped.writes_lost_off_tiles(), lost_tile_order) << S;
    EXPECT_EQ(pooled.writes_lost_off_tiles(), 0);
    EXPECT_EQ(pooled.tiles_most_at_once(), P);
    EXPECT_EQ(pooled.tiles_allocated(), mapped.tiles_allocated()) << S;
    expect_same_tiles(pooled, mapped, {2});
    // The texel path.
    DisplayMemoryBank pooled_texels(fmt, {}, P), mapped_texels(fmt, by_texel_order);
    for (DisplayMemoryBank* b : {&pooled_texels, &mapped_texels})
      for (int y = 0; y < S; ++y)
        for (int x = 0; x < S; ++x)
          if (const uint64_t w = at(x, y); w != fmt.empty_word()) b->write(2, x, y, texel_color(w), texel_depth(w));
    EXPECT_EQ(pooled_texels.writes_lost_pool_full(), lost_texel_order) << S;
    EXPECT_EQ(pooled_texels.texels_written(), mapped_texels.texels_written()) << S;
    expect_same_tiles(pooled_texels, mapped_texels, {2});
    // Faces reserved together and stored on two threads (the renderer's path): slots in face order, the pool
    // filling up on the second face after two of its tiles.
    {
      TileMap map2(S, false);
      int second = 0;
      for (int ty = 0; ty < T; ++ty)
        for (int tx = 0; tx < T; ++tx) {
          bool own = false;
          for (int y = ty * 32; y < std::min(S, ty * 32 + 32); ++y)
            for (int x = tx * 32; x < std::min(S, tx * 32 + 32); ++x) own |= at(x, y) != fmt.empty_word();
          if (!own) continue;
          map2.set(0, tx, ty, true);
          if (second++ < 2) map2.set(2, tx, ty, true);
        }
      const int64_t slots = static_cast<int64_t>(own_texels.size()) + 2;
      DisplayMemoryBank pooled2(fmt, {}, slots), mapped2(fmt, map2);
      std::array<const uint64_t*, 6> both{};
      both[0] = both[2] = words.data();
      for (DisplayMemoryBank* b : {&pooled2, &mapped2}) {
        b->reserve_faces(both, fmt.empty_word());
        std::thread other([&] { b->store_face(2, words.data(), fmt.empty_word()); });
        b->store_face(0, words.data(), fmt.empty_word());
        other.join();
      }
      EXPECT_EQ(pooled2.writes_lost_pool_full(), lost_beyond(2)) << S;
      EXPECT_EQ(mapped2.writes_lost_off_tiles(), lost_beyond(2)) << S;
      EXPECT_EQ(pooled2.tiles_most_at_once(), slots);
      expect_same_tiles(pooled2, mapped2, {0, 2});
    }
    // Both buffers share the slots: an image of P tiles shown keeps them, so the back buffer, cleared, gets none
    // of a pool of P; a pool of 2P gives it P. Drawing again on the tiles a buffer has takes no slot.
    std::vector<uint64_t> first_p = words;  // the texels of the first P tiles only
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x)
        if (!by_tile_order.has(2, x / 32, y / 32)) first_p[static_cast<size_t>(y) * static_cast<size_t>(S) + static_cast<size_t>(x)] = fmt.empty_word();
    for (const int64_t slots : {P, 2 * P}) {
      DisplayMemoryBank b(fmt, {}, slots);
      b.write_face(2, first_p.data(), fmt.empty_word());
      ASSERT_EQ(b.writes_lost_pool_full(), 0);
      b.commit();
      b.vblank();
      b.clear_back();
      const int64_t lost_before = b.writes_lost_pool_full();
      b.write_face(2, words.data(), fmt.empty_word());
      EXPECT_EQ(b.tiles_most_at_once(), slots) << slots;
      EXPECT_EQ(b.writes_lost_pool_full() - lost_before, slots == P ? all : lost_tile_order) << slots;
      const int64_t lost_again = b.writes_lost_pool_full();
      b.write_face(2, words.data(), fmt.empty_word());  // the same tiles (slotted or refused) again
      EXPECT_EQ(b.tiles_most_at_once(), slots) << slots;
      EXPECT_EQ(b.writes_lost_pool_full() - lost_again, slots == P ? all : lost_tile_order) << slots;
      // Cleared, the back buffer's refusals go too: with the shown image's P slots freed by a swap and a clear,
      // it takes P tiles again.
      b.commit();
      b.vblank();
      b.clear_back();
      b.commit();
      b.vblank();
      b.clear_back();
      const int64_t lost_last = b.writes_lost_pool_full();
      b.write_face(2, words.data(), fmt.empty_word());
      EXPECT_EQ(b.writes_lost_pool_full() - lost_last, lost_beyond(slots)) << slots;
    }
  }
}

// A memory set gives each memory's banks, every eye's, its pool; it matches a configuration whose pools are its
// own (no list and a list of zeros alike: no pool).
TEST(DisplayMemorySet, EachMemoryHasItsOwnPool) {
  MemoryConfig mc;
  mc.count = 3;
  mc.tile_pool = {0, 12, 0};
  const DisplayMemorySet set(mc, 2);
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(set.bank(e, k).pool_slots(), k == 1 ? 12 : 0);
  ArpConfig c;
  c.memory = mc;
  EXPECT_TRUE(matches(set, c));
  c.memory.tile_pool = {0, 11, 0};
  EXPECT_FALSE(matches(set, c));
  c.memory.tile_pool.clear();
  EXPECT_FALSE(matches(set, c));
  mc.tile_pool = {0, 0, 0};
  const DisplayMemorySet none(mc, 2);
  EXPECT_TRUE(matches(none, c));
}

// A memory set gives each memory's banks, every eye's, that memory's tiles.
TEST(DisplayMemorySet, EachMemoryHoldsItsOwnTiles) {
  MemoryConfig mc;
  mc.count = 2;
  mc.face_size = 64;
  mc.tiles = {"64:1/-/-/-/-/-", "64:*/*/*/*/*/*"};
  DisplayMemorySet set(mc, 2);
  for (int e = 0; e < 2; ++e) {
    EXPECT_TRUE(set.bank(e, 0).holds(0, 0, 0));
    EXPECT_FALSE(set.bank(e, 0).holds(0, 1, 0));
    EXPECT_FALSE(set.bank(e, 0).holds(5, 0, 0));
    EXPECT_TRUE(set.bank(e, 1).holds(5, 1, 1));
    set.bank(e, 0).write(0, 40, 3, 1, 1);  // tile (1, 0): lost
    set.bank(e, 1).write(0, 40, 3, 1, 1);
  }
  EXPECT_EQ(set.writes_lost_off_tiles(), 2);
  EXPECT_EQ(set.texels_written(), 2);
  // It is the memory set of a configuration with those tiles only (a frame renderer refuses another).
  ArpConfig c;
  c.memory = mc;
  EXPECT_TRUE(matches(set, c));
  c.memory.tiles.clear();
  EXPECT_FALSE(matches(set, c));
  mc.tiles = {"64:*/*/*/*/*/*"};
  EXPECT_THROW(DisplayMemorySet(mc, 1), std::invalid_argument);  // one string for two memories
  mc.tiles = {"64:*/*/*/*/*/*", "64:1"};
  EXPECT_THROW(DisplayMemorySet(mc, 1), std::invalid_argument);  // malformed
}

TEST(MemoryFormat, ColourPackingAndRounding) {
  MemoryFormat f;
  f.red_bits = 5;
  f.green_bits = 6;
  f.blue_bits = 5;
  EXPECT_EQ(f.pack_rgb8(255, 255, 255), 0xFFFFu);
  EXPECT_EQ(f.pack_rgb8(0, 0, 0), 0u);
  EXPECT_EQ(f.pack_rgb8(255, 0, 0), 0xF800u);
  EXPECT_EQ(f.pack_rgb8(0, 128, 0), 32u << 5);  // 128 * 63 / 255 = 31.6 -> 32
  EXPECT_EQ(f.empty_depth(), 0xFFFFu);
  MemoryFormat d32;
  d32.depth_bits = 32;
  EXPECT_EQ(d32.empty_depth(), 0xFFFFFFFFu);
}
