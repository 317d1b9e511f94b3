// Tearing along cut objects' seams, on hand-made object maps: which pixels
// are in the seam zone, which show a tear, which an opened crack, and the
// magnified picture of the worst window.
#include <gtest/gtest.h>

#include <stdexcept>

#include "host/error/SeamMetrics.hpp"
#include "host/error/TearImage.hpp"

using namespace arp::host;

namespace {

// 20 x 10, one eye: piece A (id 1) on the left half, piece B (id 2) on the right,
// both cut from object 0; id 3 is a wall behind (object 1).
struct TwoPieces {
  ObjectMap truth, shown;
  SeamPieces pieces;
  TwoPieces() {
    truth.resize(20, 10, 1);
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 20; ++x) truth.id[truth.index(0, x, y)] = x < 10 ? 1 : 2;
    shown = truth;
    pieces.source = {0, 0, 1};
    pieces.memory = {0, 1, 2};
  }
};

}  // namespace

TEST(SeamMetrics, AnOpenedSeamIsACrackAndATearEveryPixelOfIt) {
  TwoPieces s;
  // The seam between x = 9 and 10 opens two pixels wide on rows 2..7: the wall shows.
  for (int y = 2; y <= 7; ++y)
    for (int x = 9; x <= 10; ++x) s.shown.id[s.shown.index(0, x, y)] = 3;
  // On rows 0 and 1 one pixel shows nothing at all.
  for (int y = 0; y <= 1; ++y) s.shown.id[s.shown.index(0, 9, y)] = 0;
  const SeamMeasure m = measure_seams(s.shown, s.truth, s.pieces);
  EXPECT_EQ(m.crack_pixels, 12 + 2);
  EXPECT_EQ(m.tear_pixels, 12 + 2);
  EXPECT_EQ(m.gap_pixels, 2);
  // The seam zone: a pixel either side of the seam (columns 8..11), every row.
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      EXPECT_EQ((m.marks[s.shown.index(0, x, y)] & kSeamZone) != 0, x >= 8 && x <= 11) << x << "," << y;
      EXPECT_EQ((m.marks[s.shown.index(0, x, y)] & kCrackMark) != 0, (x == 9 || x == 10) && y <= 7 && !(x == 10 && y <= 1))
          << x << "," << y;
    }
}

TEST(SeamMetrics, NoSeamBetweenPiecesOfOneMemoryOrWiderThanThreePixels) {
  TwoPieces s;
  for (int y = 2; y <= 7; ++y) s.shown.id[s.shown.index(0, 9, y)] = 3;
  s.pieces.memory = {0, 0, 2};  // both pieces drawn together: no seam to open
  const SeamMeasure same = measure_seams(s.shown, s.truth, s.pieces);
  EXPECT_EQ(same.crack_pixels, 0);
  EXPECT_EQ(same.tear_pixels, 0);
  // Different memories but the wall four pixels wide: an object in between, not a crack.
  s.pieces.memory = {0, 1, 2};
  for (int y = 2; y <= 7; ++y)
    for (int x = 8; x <= 11; ++x) s.shown.id[s.shown.index(0, x, y)] = 3;
  const SeamMeasure wide = measure_seams(s.shown, s.truth, s.pieces);
  EXPECT_EQ(wide.crack_pixels, 0);
  EXPECT_EQ(wide.tear_pixels, 4 * 6);  // still torn against the truth
  // Identical to the truth: nothing.
  const SeamMeasure clean = measure_seams(s.truth, s.truth, s.pieces);
  EXPECT_EQ(clean.crack_pixels + clean.tear_pixels + clean.gap_pixels, 0);
}

TEST(SeamMetrics, VerticalSeamsAndBadMaps) {
  ObjectMap t;
  t.resize(6, 12, 2);
  for (int e = 0; e < 2; ++e)
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 6; ++x) t.id[t.index(e, x, y)] = y < 6 ? 1 : 2;
  ObjectMap sh = t;
  for (int y = 5; y <= 7; ++y) sh.id[sh.index(1, 3, y)] = 0;  // three pixels down the second eye
  const SeamPieces p{{4, 4}, {1, 3}};
  const SeamMeasure m = measure_seams(sh, t, p);
  EXPECT_EQ(m.crack_pixels, 3);
  EXPECT_EQ(m.gap_pixels, 3);
  ObjectMap bad = t;
  bad.id[0] = 7;
  EXPECT_THROW(measure_seams(bad, t, p), std::invalid_argument);
  ObjectMap small;
  small.resize(6, 11, 2);
  EXPECT_THROW(measure_seams(small, t, p), std::invalid_argument);
}

TEST(TearImage, TheDensestWindowMagnifiedInThreePanels) {
  TwoPieces s;
  for (int y = 2; y <= 7; ++y)
    for (int x = 9; x <= 10; ++x) s.shown.id[s.shown.index(0, x, y)] = 3;
  const SeamMeasure m = measure_seams(s.shown, s.truth, s.pieces);
  const TearWindow w = densest_window(s.shown, m.marks, kCrackMark, 4, 4);
  EXPECT_EQ(w.marked, 8);
  EXPECT_EQ(w.eye, 0);
  EXPECT_EQ(w.x, 8);  // centred on the crack's two columns 9 and 10
  EXPECT_EQ(w.y, 2);
  const TearWindow big = densest_window(s.shown, m.marks, kCrackMark, 48, 32);
  EXPECT_EQ(big.width, 20);  // clamped to the image
  EXPECT_EQ(big.height, 10);
  EXPECT_EQ(big.marked, 12);
  RgbImage shown(20, 10), truth(20, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      truth.px(x, y)[1] = 200;
      shown.px(x, y)[2] = 100;
    }
  const RgbImage img = magnified_tear(shown, truth, s.shown, m.marks, w, 3);
  EXPECT_EQ(img.width, 3 * 12 + 8);
  EXPECT_EQ(img.height, 12);
  // Window pixel (1, 0) is frame pixel (9, 2): a crack.
  const uint8_t* displayed = img.px(1 * 3 + 1, 1);
  const uint8_t* reference = img.px(16 + 1 * 3 + 1, 1);
  const uint8_t* marked = img.px(32 + 1 * 3 + 1, 1);
  EXPECT_EQ(displayed[2], 100);
  EXPECT_EQ(reference[1], 200);
  EXPECT_EQ(marked[0], 255);
  EXPECT_EQ(marked[1], 0);
  EXPECT_EQ(marked[2], 255);
  EXPECT_EQ(img.px(32 + 1, 1)[1], 128);  // (8, 2): in the seam zone, tinted cyan
  EXPECT_EQ(img.px(32 + 1, 1)[2], 100 / 2 + 128);
  const TearWindow left = densest_window(s.shown, m.marks, kSeamZone, 4, 4);
  const RgbImage wide = magnified_tear(shown, truth, s.shown, m.marks, {0, 0, 0, 4, 4, 0}, 2);
  EXPECT_EQ(wide.px(2 * 8 + 8 + 1, 1)[2], 100);  // (0, 0): far from the seam, as displayed
  EXPECT_EQ(left.x, 8);
  TearWindow outside = w;
  outside.x = 17;
  EXPECT_THROW(magnified_tear(shown, truth, s.shown, m.marks, outside, 3), std::invalid_argument);
}
