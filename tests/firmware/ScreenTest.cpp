#include <gtest/gtest.h>

#include "common/grid/MapLayers.hpp"
#include "firmware/app/Screen.hpp"

namespace nxtmap::fw {
namespace {

TEST(Screen, PixelRowsMapToBitsOfPages) {
  uint8_t frame[8][100] = {};
  Screen s(frame);
  s.pixel(3, 0, true);
  s.pixel(3, 9, true);
  s.pixel(99, 63, true);
  EXPECT_EQ(frame[0][3], 0x01);
  EXPECT_EQ(frame[1][3], 0x02);
  EXPECT_EQ(frame[7][99], 0x80);
  s.pixel(3, 9, false);
  EXPECT_EQ(frame[1][3], 0x00);
  s.pixel(100, 0, true);  // outside: ignored
  s.pixel(0, 64, true);
}

TEST(Screen, TextUsesTheFontAndAdvancesFourPixels) {
  uint8_t frame[8][100] = {};
  Screen s(frame);
  EXPECT_EQ(s.text(0, 0, "1-"), 8);
  // "1": .#. / ##. / .#. / .#. / ###
  EXPECT_FALSE(s.pixelAt(0, 0));
  EXPECT_TRUE(s.pixelAt(1, 0));
  EXPECT_TRUE(s.pixelAt(0, 1));
  EXPECT_TRUE(s.pixelAt(2, 4));
  // "-" on the middle row only
  EXPECT_TRUE(s.pixelAt(4, 2) && s.pixelAt(6, 2));
  EXPECT_FALSE(s.pixelAt(5, 1));
  EXPECT_EQ(s.number(20, 10, 1234), 36);
}

TEST(Screen, MapShowsOccupiedDarkFreeLightAndTheRobot) {
  MapStorage<64, 64> storage{};
  MapLayers map(storage.view(), 64, 64);
  ASSERT_TRUE(map.markVisited(Cell{0, 0}));
  ASSERT_TRUE(map.markVisited(Cell{1, 0}));
  ASSERT_TRUE(map.markBlocked(Cell{2, 0}));
  ASSERT_TRUE(map.markBlocked(Cell{0, 1}));
  uint8_t frame[8][100] = {};
  Screen s(frame);
  s.drawMap(map.grid(), Cell{0, 0}, Dir::West, false);  // heading pixel falls off the left edge
  // Window: x 0..2, y 0..1; north up, so y = 0 is the bottom row of the 64 pixels (row 63).
  EXPECT_FALSE(s.pixelAt(1, 63));  // free
  EXPECT_TRUE(s.pixelAt(2, 63));   // occupied
  EXPECT_TRUE(s.pixelAt(0, 62));   // occupied, one row up
  EXPECT_FALSE(s.pixelAt(0, 63));  // the robot, blink phase off
  s.drawMap(map.grid(), Cell{1, 0}, Dir::North, true);
  EXPECT_TRUE(s.pixelAt(1, 63));   // the robot, blink phase on
  EXPECT_TRUE(s.pixelAt(1, 62));   // its heading pixel (north = up)
  EXPECT_TRUE(s.pixelAt(64, 10));  // separator column
}

}  // namespace
}  // namespace nxtmap::fw
