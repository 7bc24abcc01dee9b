// Unit tests of the report library's maps: the console map (MapText) and the PNG map (MapImage).
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/report/MapImage.hpp"
#include "host/report/MapText.hpp"

namespace nxtmap::report {
namespace {

// A belief grid spelled with the display's own glyphs: ' ' free, '~' unknown, 'X' occupied.
std::function<CellState(int, int)> grid(const std::vector<std::string>& rows) {
  return [rows](int col, int row) {
    const char c = rows[static_cast<size_t>(row)][static_cast<size_t>(col)];
    return c == ' ' ? CellState::Free : c == 'X' ? CellState::Occupied : CellState::Unknown;
  };
}

struct TextCase {
  const char* name;
  std::vector<std::string> cells;
  std::optional<RobotMark> robot;
  bool rulers;
  std::string expected;
};

TEST(MapText, ExpectedStrings) {
  const std::vector<TextCase> cases = {
      {"tiny with robot facing east",
       {"X~ ", "X  "},
       RobotMark{1, 1, sim::Heading::E},
       true,
       "    012\n"
       "   +---+\n"
       " 0 |X~ |\n"
       " 1 |X> |\n"
       "   +---+\n"},
      {"robot headings and no rulers",
       {"  ", "  "},
       RobotMark{0, 0, sim::Heading::W},
       false,
       "+--+\n"
       "|< |\n"
       "|  |\n"
       "+--+\n"},
      {"robot outside is not drawn",
       {"~~"},
       RobotMark{5, 5, sim::Heading::N},
       false,
       "+--+\n"
       "|~~|\n"
       "+--+\n"},
      {"tens ruler from column 10",
       {"XXXXXXXXXXXX"},
       std::nullopt,
       true,
       "              11\n"
       "    012345678901\n"
       "   +------------+\n"
       " 0 |XXXXXXXXXXXX|\n"
       "   +------------+\n"},
  };
  for (const TextCase& c : cases) {
    SCOPED_TRACE(c.name);
    MapTextOptions o;
    o.rulers = c.rulers;
    const int w = static_cast<int>(c.cells[0].size()), h = static_cast<int>(c.cells.size());
    EXPECT_EQ(renderMapText(w, h, grid(c.cells), c.robot, o), c.expected);
  }
}

TEST(MapText, RowLabelsWidenForTallMaps) {
  std::vector<std::string> cells(101, " ");
  const std::string text = renderMapText(1, 101, grid(cells), std::nullopt);
  EXPECT_NE(text.find("\n100 | |\n"), std::string::npos);
  EXPECT_NE(text.find("\n  7 | |\n"), std::string::npos);
}

TEST(MapText, Glyphs) {
  EXPECT_EQ(headingGlyph(sim::Heading::N), '^');
  EXPECT_EQ(headingGlyph(sim::Heading::E), '>');
  EXPECT_EQ(headingGlyph(sim::Heading::S), 'v');
  EXPECT_EQ(headingGlyph(sim::Heading::W), '<');
  EXPECT_EQ(cellGlyph(CellState::Free), ' ');
  EXPECT_EQ(cellGlyph(CellState::Unknown), '~');
  EXPECT_EQ(cellGlyph(CellState::Occupied), 'X');
}

TEST(MapText, ColourWrapsCellsAndResets) {
  MapTextOptions o;
  o.color = true;
  o.rulers = false;
  const std::string text = renderMapText(3, 1, grid({"X~ "}), RobotMark{2, 0, sim::Heading::S}, o);
  EXPECT_NE(text.find("\x1b[1;97mX"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[2m~"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[1;91mv"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[0m|"), std::string::npos) << text;
}

TEST(MapText, RenderedRunShowsRobotAndFrame) {
  const sim::World world = sim::World::fromRows({"#######", "#.....#", "#..#..#", "#.....#", "#######"});
  mapping::RunConfig config;
  config.startCol = 1;
  config.startRow = 3;
  mapping::MappingRun run(world, config);
  const std::string before = renderMapText(run, MapTextOptions{false, false});
  EXPECT_NE(before.find('^'), std::string::npos) << before;
  run.runToEnd();
  const std::string after = renderMapText(run, MapTextOptions{false, false});
  const std::vector<std::string> rows = cli::test::lines(after);
  ASSERT_EQ(rows.size(), 7u) << after;
  EXPECT_EQ(rows[0], "+-------+");
  EXPECT_EQ(rows[3].substr(0, 4), "|X  ") << after;  // the middle obstacle is found
  EXPECT_EQ(rows[3].substr(4, 1), "X") << after;

  const RgbImage img = renderMapImage(run, MapImageOptions{4, true, false});
  EXPECT_EQ(img.width, 28);
  EXPECT_EQ(img.height, 20);
  uint8_t r = 0, g = 0, b = 0;
  img.pixel(3 * 4 + 2, 2 * 4 + 2, r, g, b);  // the obstacle in the middle: black
  EXPECT_EQ(r + g + b, 0);
  cli::test::TempDir tmp("img");
  std::string error;
  ASSERT_TRUE(writePng(tmp.path("m.png"), img, error)) << error;
  EXPECT_EQ(cli::test::readFile(tmp.path("m.png")).substr(1, 3), "PNG");
  EXPECT_FALSE(writePng(tmp.path("no/dir/m.png"), img, error));
  EXPECT_FALSE(error.empty());
}

// Any belief on a world (the emulated brick's radio map): each cell's colour from the belief against the world, the
// robot in its believed cell; a robot outside the world is not drawn.
TEST(MapImage, BeliefPictureColoursEachCellAgainstTheWorld) {
  const sim::World world = sim::World::fromRows({"#.##", "...."});
  const std::vector<std::string> belief = {"X~ .", "X.. "};  // X occupied, . free, ~ or space unknown
  BeliefPicture p;
  p.world = &world;
  p.belief = [&](int col, int row) {
    const char c = belief[static_cast<size_t>(row)][static_cast<size_t>(col)];
    return c == 'X' ? CellState::Occupied : c == '.' ? CellState::Free : CellState::Unknown;
  };
  p.robotCol = 2;
  p.robotRow = 1;
  struct Row {
    int col, row;
    int r, g, b;
  };
  const Row rows[] = {
      {0, 0, 0, 0, 0},        // occupied, a wall: black
      {1, 0, 160, 160, 160},  // unknown, nothing there: grey
      {2, 0, 255, 170, 170},  // unknown, a wall there: missed, light red
      {3, 0, 255, 140, 0},    // free, a wall there: wrong, orange
      {0, 1, 40, 90, 255},    // occupied, nothing there: wrong, blue
      {3, 1, 160, 160, 160},  // unknown, nothing there: grey
      {1, 1, 255, 255, 255},  // free: white
      {2, 1, 220, 0, 0},      // the robot
  };
  const RgbImage img = renderBeliefImage(p, MapImageOptions{4, true, false});
  ASSERT_EQ(img.width, 16);
  ASSERT_EQ(img.height, 8);
  for (const Row& r : rows) {
    uint8_t red = 0, green = 0, blue = 0;
    img.pixel(r.col * 4 + 2, r.row * 4 + 2, red, green, blue);
    EXPECT_EQ(std::vector<int>({red, green, blue}), std::vector<int>({r.r, r.g, r.b})) << r.col << "," << r.row;
  }
  p.robotCol = 4;  // outside: the cell keeps its own colour
  uint8_t red = 0, green = 0, blue = 0;
  renderBeliefImage(p, MapImageOptions{4, true, false}).pixel(2 * 4 + 2, 1 * 4 + 2, red, green, blue);
  EXPECT_EQ(red + green + blue, 3 * 255);
}

}  // namespace
}  // namespace nxtmap::report

TEST(MapImage, PictureOfALargeWorldKeepsWithinItsBound) {
  struct Row {
    int side, asked, px;
  };
  const Row rows[] = {{22, 8, 8},   {1024, 8, 8},  {1025, 8, 7},  {4096, 8, 2},
                      {8192, 8, 1}, {16384, 8, 1}, {10, 100, 64}, {10, 0, 1}};
  for (const Row& r : rows) {
    EXPECT_EQ(nxtmap::report::pictureCellPx(r.side, r.asked), r.px) << r.side << " cells at " << r.asked;
    if (r.side <= nxtmap::report::kMaxPictureSide) {
      EXPECT_LE(r.side * nxtmap::report::pictureCellPx(r.side, r.asked), nxtmap::report::kMaxPictureSide);
    }
  }
}
