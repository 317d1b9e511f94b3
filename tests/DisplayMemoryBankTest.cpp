#include <gtest/gtest.h>

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
