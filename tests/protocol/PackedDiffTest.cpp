// Comparing and copying packed 2-bit tori without decoding cell by cell (MapSync's scan).
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "common/protocol/PackedDiff.hpp"

namespace nxtmap::protocol {
namespace {

uint8_t cellOf(const uint8_t* t, uint32_t i) { return static_cast<uint8_t>((t[i >> 2] >> ((i & 3u) * 2u)) & 3u); }

// The obvious byte-by-byte answer, to check the word-wise one against.
size_t naiveFirstDifference(const uint8_t* a, const uint8_t* b, size_t from, size_t end) {
  size_t i = from;
  while (i < end && a[i] == b[i]) ++i;
  return i;
}

TEST(PackedDiff, FirstDifferenceTable) {
  struct Row {
    size_t from, end;
    std::vector<size_t> differing;  // byte indices where b differs from a
    size_t expected;
  };
  const Row rows[] = {
      {0, 64, {}, 64},         // equal: the end
      {0, 64, {0}, 0},         // the first byte
      {0, 64, {63}, 63},       // the last byte
      {0, 64, {17, 40}, 17},   // the first of several
      {18, 64, {17, 40}, 40},  // differences before `from` are not looked at
      {0, 17, {17, 40}, 17},   // nor at or after `end`
      {5, 5, {5}, 5},          // an empty range
      {3, 37, {36}, 36},       // unaligned start, difference in the tail bytes
      {1, 64, {2}, 2},         // before the first aligned word
      {0, 64, {16}, 16},       // right after the first 16-byte block
      {0, 64, {15}, 15},       // the last byte of the first block
  };
  for (const Row& r : rows) {
    alignas(4) uint8_t a[64], b[64];
    for (size_t i = 0; i < 64; ++i) a[i] = b[i] = static_cast<uint8_t>(i * 37u);
    for (size_t d : r.differing) b[d] = static_cast<uint8_t>(b[d] ^ 0x40u);
    EXPECT_EQ(firstDifference(a, b, r.from, r.end), r.expected) << "from " << r.from << " end " << r.end;
  }
}

// All alignments of both buffers (word path when they share one, byte path when not), all
// positions of a single difference: the same answer as the byte loop.
TEST(PackedDiff, FirstDifferenceAgreesWithBytesForEveryAlignment) {
  alignas(4) uint8_t bufA[96], bufB[96];
  for (size_t offA = 0; offA < 4; ++offA) {
    for (size_t offB = 0; offB < 4; ++offB) {
      uint8_t* a = bufA + offA;
      uint8_t* b = bufB + offB;
      for (size_t d = 0; d <= 80; ++d) {  // d = 80: no difference
        for (size_t i = 0; i < 80; ++i) a[i] = b[i] = static_cast<uint8_t>(i * 11u + 3u);
        if (d < 80) b[d] = static_cast<uint8_t>(b[d] + 1u);
        for (size_t from : {size_t{0}, size_t{1}, size_t{7}}) {
          ASSERT_EQ(firstDifference(a, b, from, 80), naiveFirstDifference(a, b, from, 80))
              << "offsets " << offA << "," << offB << " difference at " << d << " from " << from;
        }
      }
    }
  }
}

TEST(PackedDiff, DifferingCellsTable) {
  struct Row {
    uint8_t a, b, mask;
  };
  const Row rows[] =
      {
          {0x00, 0x00, 0x0}, {0xFF, 0xFF, 0x0}, {0x00, 0x01, 0x1}, {0x00, 0x02, 0x1},
          {0x00, 0x03, 0x1}, {0x00, 0x04, 0x2}, {0x00, 0x08, 0x2}, {0x00, 0x30, 0x4},
          {0x00, 0x40, 0x8}, {0x00, 0x80, 0x8}, {0x1B, 0xE4, 0xF},  // 0,1,2,3 against 3,2,1,0: every cell
          {0x1B, 0x1F, 0x2},                                        // cell 1: 2 -> 3
          {0xAA, 0x55, 0xF}, {0x55, 0x54, 0x1},
      };
  for (const Row& r : rows) {
    EXPECT_EQ(differingCells(r.a, r.b), r.mask) << std::hex << int(r.a) << " " << int(r.b);
    EXPECT_EQ(differingCells(r.b, r.a), r.mask);
  }
  EXPECT_EQ(lowestCell(0x1), 0);
  EXPECT_EQ(lowestCell(0xE), 1);
  EXPECT_EQ(lowestCell(0xC), 2);
  EXPECT_EQ(lowestCell(0x8), 3);
}

TEST(PackedDiff, CellDiffersMatchesTheDecodedCells) {
  std::mt19937 rng(3);
  uint8_t a[16], b[16];
  for (int i = 0; i < 16; ++i) {
    a[i] = static_cast<uint8_t>(rng());
    b[i] = static_cast<uint8_t>(rng() & 0x0Fu) == 0 ? a[i] : static_cast<uint8_t>(a[i] ^ (rng() & 0xFFu));
  }
  for (uint32_t c = 0; c < 64; ++c) EXPECT_EQ(cellDiffers(a, b, c), cellOf(a, c) != cellOf(b, c)) << c;
}

// Every start and length inside a 12-byte torus: the packed run holds exactly the cells, in
// order, with zero padding; copy and set touch exactly the cells asked for.
TEST(PackedDiff, ExtractCopyAndSetEveryRange) {
  std::mt19937 rng(9);
  uint8_t torus[12], other[12];
  for (uint8_t& x : torus) x = static_cast<uint8_t>(rng());
  for (uint8_t& x : other) x = static_cast<uint8_t>(rng());
  const uint32_t total = 48;
  for (uint32_t first = 0; first < total; ++first) {
    for (uint32_t count = 0; first + count <= total && count <= 40; ++count) {
      uint8_t packed[11];
      std::memset(packed, 0xA5, sizeof packed);
      extractCells(torus, first, count, packed);
      for (uint32_t k = 0; k < count; ++k) ASSERT_EQ(cellOf(packed, k), cellOf(torus, first + k)) << first << "+" << k;
      if (count % 4 != 0) {
        for (uint32_t k = count; k % 4 != 0; ++k) {
          ASSERT_EQ(cellOf(packed, k), 0) << "padding after " << count;
        }
      }
      if (count > 0) {
        ASSERT_EQ(packed[(count + 3) / 4], 0xA5) << "wrote past the run";
      }

      uint8_t copy[12], set[12];
      std::memcpy(copy, other, sizeof copy);
      std::memcpy(set, other, sizeof set);
      copyCells(torus, copy, first, count);
      setCells(set, first, count, 3);
      for (uint32_t c = 0; c < total; ++c) {
        const bool inside = c >= first && c < first + count;
        ASSERT_EQ(cellOf(copy, c), inside ? cellOf(torus, c) : cellOf(other, c))
            << first << "," << count << " cell " << c;
        ASSERT_EQ(cellOf(set, c), inside ? 3 : cellOf(other, c)) << first << "," << count << " cell " << c;
      }
    }
  }
}

TEST(PackedDiff, ExtractDoesNotReadPastTheLastCell) {
  // The run ends at the torus's last cell with an unaligned start: the byte after the torus
  // must not be needed (a sanitizer build would flag the read; here it is also poisoned).
  std::vector<uint8_t> t(4, 0);
  t[3] = 0xC0;  // cell 15 = 3
  uint8_t packed[2] = {0xFF, 0xFF};
  extractCells(t.data(), 13, 3, packed);
  EXPECT_EQ(packed[0], 0x30);  // cells 13, 14, 15 = 0, 0, 3
}

}  // namespace
}  // namespace nxtmap::protocol
