// The console's command lines (parsed before anything is sent) and the map picture `export` writes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/console/ConsoleCommand.hpp"
#include "host/report/GridImage.hpp"

namespace nxtmap::console {
namespace {

using K = ConsoleCommand::Kind;

TEST(ConsoleCommand, EachLineParsesToItsCommand) {
  struct Case {
    std::string line;
    K kind;
    int col, row;
    std::string name;
    bool near;
    double seconds;
  };
  const Case cases[] = {
      {"", K::Empty, 0, 0, "", false, 0},
      {"# a comment", K::Empty, 0, 0, "", false, 0},
      {"explore", K::Explore, 0, 0, "", false, 0},
      {"explore house", K::ExploreHouse, 0, 0, "", false, 0},
      {"  stop  ", K::Stop, 0, 0, "", false, 0},
      {"calibrate", K::Calibrate, 0, 0, "", false, 300},
      {"calibrate 90", K::Calibrate, 0, 0, "", false, 90},
      {"goto 18 3", K::Goto, 18, 3, "", false, 0},
      {"goto near sofa", K::GotoNear, 0, 0, "sofa", false, 0},
      {"label door 4 0", K::Label, 4, 0, "door", false, 0},
      {"rooms", K::Rooms, 0, 0, "", false, 0},
      {"route 1 2 3", K::Route, 2, 3, "1", false, 0},
      {"route kitchen 0 7", K::Route, 0, 7, "kitchen", false, 0},
      {"route near sofa", K::Route, 0, 0, "sofa", true, 0},
      {"save out/house", K::Save, 0, 0, "out/house", false, 0},
      {"save room.yaml", K::Save, 0, 0, "room.yaml", false, 0},
      {"export room.png", K::Export, 0, 0, "room.png", false, 0},
      {"status", K::Status, 0, 0, "", false, 0},
      {"battery", K::Battery, 0, 0, "", false, 0},
      {"map", K::Map, 0, 0, "", false, 0},
      {"wait explored", K::Wait, 0, 0, "explored", false, 600},
      {"wait goal 60", K::Wait, 0, 0, "goal", false, 60},
      {"wait house 900", K::Wait, 0, 0, "house", false, 900},
      {"help", K::Help, 0, 0, "", false, 0},
      {"? me", K::Help, 0, 0, "", false, 0},
      {"quit", K::Quit, 0, 0, "", false, 0},
      {"exit now", K::Quit, 0, 0, "", false, 0},
  };
  for (const Case& c : cases) {
    const ConsoleCommand p = parseConsoleCommand(c.line);
    EXPECT_EQ(p.kind, c.kind) << c.line;
    EXPECT_EQ(p.col, c.col) << c.line;
    EXPECT_EQ(p.row, c.row) << c.line;
    EXPECT_EQ(p.name, c.name) << c.line;
    EXPECT_EQ(p.near, c.near) << c.line;
    EXPECT_EQ(p.seconds, c.seconds) << c.line;
  }
}

TEST(ConsoleCommand, AMalformedLineIsOneMessageNamingTheRightForm) {
  struct Case {
    std::string line, message;
  };
  const Case cases[] = {
      {"explore now", "usage: explore  or  explore house"},
      {"explore house now", "usage: explore  or  explore house"},
      {"map 1", "usage: map"},
      {"goto 1", "usage: goto C R  or  goto near LABEL"},
      {"goto a 2", "column 'a' is not a cell number (0, 1, 2, ...)"},
      {"goto 1 123456", "row '123456' is not a cell number"},
      {"label x 1", "usage: label NAME C R"},
      {"route 1 2", "usage: route ROOM C R  or  route near LABEL"},
      {"save", "usage: save DIR  or  save FILE.yaml"},
      {"export room.jpg", "export needs a .png file name: export FILE.png"},
      {"wait", "usage: wait explored|goal|house [SECONDS]"},
      {"wait rooms", "usage: wait explored|goal|house [SECONDS]"},
      {"wait goal 0", "wait: SECONDS must be at least 1"},
      {"wait goal x", "wait: SECONDS 'x' is not a whole number of seconds (0, 1, 2, ...)"},
      {"calibrate 1 2", "usage: calibrate [SECONDS]"},
      {"calibrate 0", "calibrate: SECONDS must be at least 1"},
      {"calibrate soon", "calibrate: SECONDS 'soon' is not a whole number of seconds (0, 1, 2, ...)"},
      {"fly 1 2", "unknown command 'fly' (type help for the list)"},
  };
  for (const Case& c : cases) {
    try {
      parseConsoleCommand(c.line);
      ADD_FAILURE() << c.line << ": accepted";
    } catch (const ConsoleError& e) {
      EXPECT_EQ(std::string(e.what()), c.message) << c.line;
    }
  }
}

// The export picture: each cell a px x px block of its grey, the robot a red square inset 1 px.
TEST(GridImage, CellsAreGreyBlocksAndTheRobotARedSquare) {
  const CellState cells[2][3] = {{CellState::Free, CellState::Unknown, CellState::Occupied},
                                 {CellState::Occupied, CellState::Free, CellState::Unknown}};
  const auto at = [&](int col, int row) { return cells[row][col]; };
  const report::RgbImage img = report::renderGridImage(3, 2, at, report::RobotMark{1, 1}, {4});
  ASSERT_EQ(img.width, 12);
  ASSERT_EQ(img.height, 8);
  struct Case {
    int x, y;
    uint8_t r, g, b;
  };
  const Case cases[] = {
      {0, 0, 255, 255, 255}, {3, 3, 255, 255, 255},  {4, 0, 160, 160, 160}, {8, 3, 0, 0, 0},
      {0, 4, 0, 0, 0},       {4, 4, 255, 255, 255},  {5, 5, 220, 30, 30},   {6, 6, 220, 30, 30},
      {7, 7, 255, 255, 255}, {11, 7, 160, 160, 160},
  };
  for (const Case& c : cases) {
    uint8_t r = 0, g = 0, b = 0;
    img.pixel(c.x, c.y, r, g, b);
    EXPECT_EQ(std::vector<int>({r, g, b}), std::vector<int>({c.r, c.g, c.b})) << c.x << "," << c.y;
  }
  const report::RgbImage outside = report::renderGridImage(3, 2, at, report::RobotMark{3, 0}, {4});
  EXPECT_EQ(outside.rgb, report::renderGridImage(3, 2, at, std::nullopt, {4}).rgb);
}

}  // namespace
}  // namespace nxtmap::console
