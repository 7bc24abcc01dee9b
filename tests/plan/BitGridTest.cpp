// BitGrid: packing of a padded grid into row and column bitsets, and the block scans of jump point search,
// from input / expected tables (single words, scans across word boundaries, the ends of a line).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/plan/BitGrid.hpp"
#include "host/plan/Traversability.hpp"
#include "tests/plan/PlanTestSupport.hpp"

namespace nxtmap::plan {
namespace {

// A line of bits from text, position 0 first: '1' set, anything else clear.
std::vector<uint64_t> line(const std::string& text, int words) {
  std::vector<uint64_t> v(static_cast<size_t>(words), 0);
  for (size_t p = 0; p < text.size(); ++p) {
    if (text[p] == '1') v[p / 64] |= uint64_t{1} << (p % 64);
  }
  return v;
}

// A line of `length` cells of `fill`, with `mark` from `from` to `to` inclusive.
std::string run(int length, char fill, int from, int to, char mark) {
  std::string s(static_cast<size_t>(length), fill);
  for (int p = from; p <= to; ++p) s[static_cast<size_t>(p)] = mark;
  return s;
}

struct ScanCase {
  const char* name;
  std::string before, line, after;
  int from;
  int up;    // expected scanUp
  int down;  // expected scanDown
};

TEST(BitGrid, ScansFindTheFirstBlockedCellOrForcedNeighbour) {
  const std::string open8 = "11111111";
  const std::vector<ScanCase> cases = {
      // Open corridor with walls on both sides: stops only at the blocked ends.
      {"corridor", "00000000", "01111110", "00000000", 3, 7, 0},
      // Side line turns open after a blocked cell: forced at 4 going up; at 2 going down (open at 2, blocked at 3).
      {"side opens", "11101111", "01111110", "00000000", 1, 4, 0},
      {"side opens, down", "11101111", "01111110", "00000000", 6, 7, 2},
      // The other side line works the same.
      {"after side", "00000000", "01111110", "00011000", 1, 3, 0},
      {"after side, down", "00000000", "01111110", "00011000", 6, 7, 4},
      // A side open all along forces nothing.
      {"open sides", open8, "01111110", open8, 2, 7, 0},
      // Start on the stop itself.
      {"start on block", "00000000", "01101110", "00000000", 3, 3, 3},
      // Every side pattern at once: blocked line cell first.
      {"block first", "00000011", "01110111", "00000000", 1, 4, 0},
  };
  for (const ScanCase& c : cases) {
    const auto b = line(c.before, 1), l = line(c.line, 1), a = line(c.after, 1);
    EXPECT_EQ(BitGrid::scanUp(b.data(), l.data(), a.data(), 1, c.from), c.up) << c.name;
    EXPECT_EQ(BitGrid::scanDown(b.data(), l.data(), a.data(), 1, c.from), c.down) << c.name;
  }
}

TEST(BitGrid, ScansCrossWordBoundaries) {
  const int n = 200, words = 4;  // 256 bits, 200 used
  // A line open from 1 to 198, walled sides: the stops are the ends, far across words.
  const auto wall = line(std::string(n, '0'), words);
  const auto l = line(run(n, '0', 1, 198, '1'), words);
  EXPECT_EQ(BitGrid::scanUp(wall.data(), l.data(), wall.data(), words, 5), 199);
  EXPECT_EQ(BitGrid::scanDown(wall.data(), l.data(), wall.data(), words, 190), 0);
  // A side opening exactly at a word boundary (blocked at 63, open from 64): forced at 64 going up.
  const auto side = line(run(n, '1', 60, 63, '0'), words);
  EXPECT_EQ(BitGrid::scanUp(side.data(), l.data(), wall.data(), words, 10), 64);
  EXPECT_EQ(BitGrid::scanUp(side.data(), l.data(), wall.data(), words, 60), 64);
  EXPECT_EQ(BitGrid::scanUp(side.data(), l.data(), wall.data(), words, 0), 0);  // the line's own blocked end
  // Going down, the side is open at 59 and blocked at 60: forced at 59.
  EXPECT_EQ(BitGrid::scanDown(side.data(), l.data(), wall.data(), words, 150), 59);
  // A side blocked at 128 alone: forced at 127 going down, at 129 going up.
  const auto side2 = line(run(n, '1', 128, 128, '0'), words);
  EXPECT_EQ(BitGrid::scanDown(side2.data(), l.data(), wall.data(), words, 180), 127);
  EXPECT_EQ(BitGrid::scanUp(side2.data(), l.data(), wall.data(), words, 100), 129);
  // No stop in the line at all: the ends are reported as words * 64 and -1.
  const auto all = line(std::string(static_cast<size_t>(words * 64), '1'), words);
  EXPECT_EQ(BitGrid::scanUp(all.data(), all.data(), all.data(), words, 3), words * 64);
  EXPECT_EQ(BitGrid::scanDown(all.data(), all.data(), all.data(), words, 250), -1);
}

TEST(BitGrid, RowsAndColumnsHoldTheTraversabilityIncludingPadding) {
  // 70 columns: rows span two words; the padding ring is blocked.
  std::vector<std::string> rows(3, std::string(70, '.'));
  rows[1][0] = '#';
  rows[1][64] = '#';
  rows[2][69] = '?';
  const Traversability grid(test::mapFromRows(rows));
  const BitGrid& b = grid.bits();
  EXPECT_EQ(b.rowWords(), 2);     // 72 padded columns
  EXPECT_EQ(b.columnWords(), 1);  // 5 padded rows
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 72; ++x) {
      const bool expected = grid.passable(MapCell{x - 1, y - 1});
      EXPECT_EQ(b.open(x, y), expected) << x << "," << y;
      EXPECT_EQ(BitGrid::test(b.column(x), y), expected) << x << "," << y;
    }
  }
  EXPECT_FALSE(b.open(1, 2));
  EXPECT_FALSE(b.open(65, 2));
  EXPECT_FALSE(b.open(70, 3));
  EXPECT_TRUE(b.open(70, 2));
}

}  // namespace
}  // namespace nxtmap::plan
