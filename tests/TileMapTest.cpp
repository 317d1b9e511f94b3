#include <gtest/gtest.h>

#include <random>
#include <string>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/TileMap.hpp"

using namespace arp::dp;

// The text form, worked by hand: the face size, then faces of 64 texels are 2 x 2 tiles, tile k = ty x 2 + tx
// at bit k of one hex digit. +X holds (0,0) and (1,1): bits 0 and 3, 9; -X every tile; +Y none; -Y (1,0): bit 1, 2.
TEST(TileMap, TheTextIsSixFacesOfHexDigitsTileByTile) {
  TileMap m(64, false);
  m.set(0, 0, 0, true);
  m.set(0, 1, 1, true);
  for (int t = 0; t < 4; ++t) m.set(1, t % 2, t / 2, true);
  m.set(3, 1, 0, true);
  EXPECT_EQ(m.text(), "64:9/*/-/2/-/-");
  EXPECT_EQ(m.tiles(), 2 + 4 + 1);
  EXPECT_FALSE(m.every_tile());
  EXPECT_TRUE(m.every_tile(1));
  TileMap back;
  std::string why;
  ASSERT_TRUE(TileMap::parse("64:9/*/-/2/-/-", 64, back, why)) << why;
  for (int f = 0; f < 6; ++f)
    for (int t = 0; t < 4; ++t) EXPECT_EQ(back.has(f, t % 2, t / 2), m.has(f, t % 2, t / 2)) << f << " " << t;
  ASSERT_TRUE(TileMap::parse("64:9/F/0/2/0/0", 64, back, why)) << why;  // digits for every tile and for none
  EXPECT_EQ(back.text(), "64:9/*/-/2/-/-");
  EXPECT_TRUE(TileMap().every_tile());
  EXPECT_TRUE(TileMap().has(5, 1000, 1000));  // no face size: every tile of any
}

// Random maps read back as written at a face size that is and two that are not a multiple of the tile
// (641: 21 x 21 tiles, 441 bits in 111 digits, the last three bits padding).
TEST(TileMap, AnyMapReadsBackAsWritten) {
  std::mt19937 rng(11);
  for (const int S : {512, 641, 20}) {
    TileMap m(S, false);
    const int T = m.tiles_per_row();
    EXPECT_EQ(T, (S + 31) / 32);
    for (int f = 0; f < 6; ++f)
      for (int ty = 0; ty < T; ++ty)
        for (int tx = 0; tx < T; ++tx) m.set(f, tx, ty, f == 1 || (f != 4 && rng() % 3 == 0));
    TileMap back;
    std::string why;
    ASSERT_TRUE(TileMap::parse(m.text(), S, back, why)) << why;
    EXPECT_EQ(back.text(), m.text());
    for (int f = 0; f < 6; ++f)
      for (int ty = 0; ty < T; ++ty)
        for (int tx = 0; tx < T; ++tx) ASSERT_EQ(back.has(f, tx, ty), m.has(f, tx, ty)) << S << " " << f;
    if (S == 641) {
      EXPECT_EQ(m.text().find('/'), 4u + 111u);  // "641:" and the first face's digits
    }
  }
}

// A malformed text is refused naming the face and what is wrong.
TEST(TileMap, AMalformedTextNamesTheFaceAndTheFault) {
  auto why_not = [](const std::string& text, int S) {
    TileMap m;
    std::string why;
    EXPECT_FALSE(TileMap::parse(text, S, m, why)) << text;
    return why;
  };
  EXPECT_NE(why_not("64:*/*/*/*/*", 64).find("has 5 fields"), std::string::npos);
  EXPECT_NE(why_not("64:*/*/*/*/*/*/*", 64).find("more than six fields"), std::string::npos);
  EXPECT_NE(why_not("64:*/*/ff/*/*/*", 64).find("face +Y (field 3) has 2 characters"), std::string::npos);
  EXPECT_NE(why_not("64:*/*/*/g/*/*", 64).find("face -Y (field 4) has 'g'"), std::string::npos);
  EXPECT_NE(why_not("*/*/*/*/*/*", 64).find("must begin with the face size it was listed for and a colon (\"64:\")"), std::string::npos);
  // 641 and 660 both have 21 x 21 tiles: the list says which it was made for.
  EXPECT_NE(why_not("641:*/*/*/*/*/*", 660).find("was listed for faces of 641 texels; memory.face_size is 660"), std::string::npos);
  // 641: 441 tiles, the last digit's bit 0 is tile 440, bits 1-3 padding.
  const std::string ok(111, '0');
  std::string pad = ok;
  pad.back() = '2';
  EXPECT_NE(why_not("641:*/*/*/*/*/" + pad, 641).find("face -Z (field 6)'s last digit sets bit 441"), std::string::npos);
  TileMap m;
  std::string why;
  pad.back() = '1';
  EXPECT_TRUE(TileMap::parse("641:*/*/*/*/*/" + pad, 641, m, why)) << why;
  EXPECT_TRUE(m.has(5, 20, 20));
  EXPECT_EQ(m.tiles(5), 1);
}

// The configuration: one string per memory or none, each well formed for the face size, no tile on a face
// memory.faces leaves out.
TEST(TileMap, TheConfigurationChecksTheTilesAgainstTheMemories) {
  ArpConfig c;
  c.memory.count = 2;
  c.memory.face_size = 64;
  EXPECT_TRUE(validate(c).empty());
  c.memory.tiles = {"64:*/*/*/*/*/*"};
  auto issues = validate(c);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].key, "memory.tiles");
  EXPECT_NE(issues[0].reason.find("has 1 strings and memory.count is 2"), std::string::npos) << issues[0].reason;
  c.memory.tiles = {"64:*/*/*/*/*/*", "64:1/-/-/-/-/ff"};
  issues = validate(c);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_NE(issues[0].reason.find("memory 1: face -Z (field 6) has 2 characters"), std::string::npos) << issues[0].reason;
  c.memory.tiles = {"64:*/*/*/*/*/*", "64:1/-/-/-/-/f"};
  EXPECT_TRUE(validate(c).empty());
  c.memory.faces = {1, 1, 1, 1, 1, 0};
  issues = validate(c);
  ASSERT_EQ(issues.size(), 2u);  // both memories hold tiles of -Z
  EXPECT_NE(issues[0].reason.find("memory 0 holds tiles on face -Z, which memory.faces leaves out"), std::string::npos) << issues[0].reason;
  c.memory.tiles = {"64:*/*/*/*/*/-", "64:1/-/-/-/-/0"};
  EXPECT_TRUE(validate(c).empty());
  c.memory.face_size = 80;  // 3 x 3 tiles: the strings no longer fit, nor say this face size
  issues = validate(c);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].key, "memory.tiles");
  EXPECT_NE(issues[0].reason.find("memory 0: was listed for faces of 64 texels"), std::string::npos) << issues[0].reason;
}
