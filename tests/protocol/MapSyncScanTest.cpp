// MapSync's scan: finding pending cells byte-wise, resuming where a full delta stopped, and
// the work it does (bytes compared, cells decoded) per delta.
#include <gtest/gtest.h>

#include <random>

#include "common/protocol/MapSync.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol {
namespace {

using test::MirrorMap;
using test::OwnedGrid;

// Torus index of (x, y) on the 64 x 64 test grid.
uint32_t indexOf(int x, int y) { return static_cast<uint32_t>(y & 63) * 64u + static_cast<uint32_t>(x & 63); }

void setCell(RoomGrid& g, int x, int y, CellState s) {
  ASSERT_TRUE(g.set(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, s));
}

int drain(MapSync& sync, MirrorMap& mirror, uint16_t& seq, uint32_t now) {
  int n = 0;
  Payload p;
  while (true) {
    seq = nextSeq(seq);
    if (!sync.buildDelta(seq, now, p)) break;
    EXPECT_TRUE(mirror.apply(p.bytes, p.size));
    sync.acknowledge(seq, 0, now);
    ++n;
  }
  return n;
}

// First run index of a delta payload.
uint16_t firstRunIndex(const Payload& p) {
  return static_cast<uint16_t>(p.bytes[kDeltaHeaderSize] | (p.bytes[kDeltaHeaderSize + 1] << 8));
}

TEST(MapSyncScan, NextPendingTable) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  // Pending cells at torus indices 5, 6, 130, 4095.
  setCell(o.grid, 5, 0, CellState::Free);
  setCell(o.grid, 6, 0, CellState::Occupied);
  setCell(o.grid, 2, 2, CellState::Free);
  setCell(o.grid, -1, -1, CellState::Free);
  ASSERT_EQ(indexOf(2, 2), 130u);
  ASSERT_EQ(indexOf(-1, -1), 4095u);
  struct Row {
    uint32_t from, end, expected;
  };
  const Row rows[] = {
      {0, 4096, 5},      {5, 4096, 5},    {6, 4096, 6},       {7, 4096, 130},
      {131, 4096, 4095}, {0, 5, 5},  // none in [0, 5): the end
      {1, 3, 3},                     // unaligned both ends, nothing inside
      {3, 6, 5},                     // unaligned start, the difference in a partial last byte
      {129, 131, 130},   {130, 130, 130}, {4095, 4096, 4095}, {4000, 4095, 4095},
  };
  for (const Row& r : rows) EXPECT_EQ(sync.nextPending(r.from, r.end), r.expected) << r.from << ".." << r.end;
  EXPECT_TRUE(sync.pending());
  drain(sync, mirror, seq, 0);
  EXPECT_FALSE(sync.pending());
  EXPECT_EQ(sync.nextPending(0, 4096), 4096u);
  EXPECT_TRUE(mirror.equals(o.grid));
}

TEST(MapSyncScan, AFullDeltaResumesWhereItStoppedAndWrapsRound) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  EXPECT_EQ(sync.resumeIndex(), 0u);
  // Rows 0..9 fully free: 640 cells, more than one delta (at most (112 - 12) / 19 = 5 runs of 64).
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 64; ++x) setCell(o.grid, x, y, CellState::Free);
  }
  Payload p;
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  MapDeltaReader r(p.bytes, p.size);
  ASSERT_TRUE(r.validate());
  uint32_t sent = 0;
  Cell c;
  CellState st;
  while (r.next(c, st)) ++sent;
  EXPECT_GT(sent, 300u);  // five whole rows and part of the sixth
  EXPECT_LT(sent, 640u);
  // The cells sent are 0 .. sent - 1; the next scan starts at the byte holding cell `sent`.
  const uint32_t stop = sync.resumeIndex();
  EXPECT_EQ(stop, sent & ~3u);
  EXPECT_EQ(sync.nextPending(0, 4096), sent);
  ASSERT_TRUE(mirror.apply(p.bytes, p.size));
  sync.acknowledge(seq, 0, 0);
  // A change BEFORE the resume position waits for the wrap: the next delta starts at `stop`.
  setCell(o.grid, 0, 0, CellState::Occupied);
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_EQ(firstRunIndex(p), sent);
  ASSERT_TRUE(mirror.apply(p.bytes, p.size));
  sync.acknowledge(seq, 0, 0);
  drain(sync, mirror, seq, 0);
  EXPECT_TRUE(mirror.equals(o.grid));
  EXPECT_EQ(mirror.cells.at({0, 0}), CellState::Occupied);
  EXPECT_FALSE(sync.pending());
}

TEST(MapSyncScan, ADeltaThatHasRoomKeepsTheResumePosition) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  setCell(o.grid, 3, 7, CellState::Free);
  Payload p;
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_EQ(sync.resumeIndex(), 0u);
  // A restart (new epoch) scans from 0 again.
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 64; ++x) setCell(o.grid, x, y, CellState::Occupied);
  }
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_GT(sync.resumeIndex(), 0u);
  sync.restart();
  EXPECT_EQ(sync.resumeIndex(), 0u);
}

// Changes that keep coming early in the grid do not starve a change at its end.
TEST(MapSyncScan, LateChangesAreNotStarvedByEarlyOnes) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  setCell(o.grid, 63, 63, CellState::Occupied);
  bool arrived = false;
  for (int round = 0; round < 8 && !arrived; ++round) {
    // Every round rewrites rows 0..7 (more than a delta holds).
    const CellState s = round % 2 ? CellState::Free : CellState::Occupied;
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 64; ++x) setCell(o.grid, x, y, s);
    }
    Payload p;
    ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
    ASSERT_TRUE(mirror.apply(p.bytes, p.size));
    sync.acknowledge(seq, 0, 0);
    const auto it = mirror.cells.find({63, 63});
    arrived = it != mirror.cells.end() && it->second == CellState::Occupied;
  }
  EXPECT_TRUE(arrived) << "cell (63,63) still not sent after 8 full deltas";
}

// The work per scan: a quiet scan compares the 1 KiB once and decodes no cell; a delta decodes
// only the cells of its runs and the gaps they bridge.
TEST(MapSyncScan, WorkIsBoundedByTheChanges) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  for (int y = -20; y < 20; ++y) {
    for (int x = -20; x < 20; ++x) setCell(o.grid, x, y, (x + y) % 3 ? CellState::Free : CellState::Occupied);
  }
  drain(sync, mirror, seq, 0);
  const MapSync::Work w0 = sync.work();
  Payload p;
  EXPECT_FALSE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_EQ(sync.work().bytesCompared - w0.bytesCompared, 1024u);
  EXPECT_EQ(sync.work().cellsExamined - w0.cellsExamined, 0u);

  setCell(o.grid, 10, 10, CellState::Occupied);
  setCell(o.grid, 12, 10, CellState::Occupied);
  const MapSync::Work w1 = sync.work();
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_LE(sync.work().bytesCompared - w1.bytesCompared, 1024u);  // each byte at most once
  // The run's 3 cells, the gap of kMaxGap + 1 after it that ends the run, the rest of its last byte.
  EXPECT_LE(sync.work().cellsExamined - w1.cellsExamined, 3u + MapSync::kMaxGap + 1u + 3u);
  ASSERT_TRUE(mirror.apply(p.bytes, p.size));
  EXPECT_TRUE(mirror.equals(o.grid));
}

// Many changes per delta, heavy losses and timeouts (so deltas are full, shrink to the smallest
// payload and resume at odd places): once the grid is quiet and the link works, equal.
TEST(MapSyncScan, FullDeltasWithLossesAndResumesAlwaysConverge) {
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    std::mt19937 rng(seed);
    OwnedGrid<> o;
    MapSync sync(o.grid, o.shadow, 60);
    MirrorMap mirror;
    uint16_t seq = 0;
    uint32_t now = 0;
    uint32_t resumedOdd = 0;
    for (int step = 0; step < 300; ++step) {
      now += 10;
      const int changes = static_cast<int>(rng() % 120);
      for (int k = 0; k < changes; ++k) {
        const int x = static_cast<int>(rng() % 64) - 32, y = static_cast<int>(rng() % 64) - 32;
        ASSERT_TRUE(
            o.grid.set(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, static_cast<CellState>(1 + rng() % 2)));
      }
      sync.expire(now);
      Payload p;
      for (int d = 0; d < 3 && sync.buildDelta(seq = nextSeq(seq), now, p); ++d) {
        if (sync.resumeIndex() % 64 != 0) ++resumedOdd;
        if (rng() % 2 == 0) {  // half of the deltas are lost
          ASSERT_TRUE(mirror.apply(p.bytes, p.size));
          if (rng() % 2 == 0) sync.acknowledge(seq, 0, now + 3);  // and half of the acks
        }
      }
      if (rng() % 151 == 0) sync.linkLost();
    }
    EXPECT_GT(resumedOdd, 0u) << "seed " << seed << ": the scan never resumed inside a row";
    for (int i = 0; i < 400 && (sync.pending() || sync.inFlight() > 0); ++i) {
      now += 100;
      sync.expire(now);
      drain(sync, mirror, seq, now);
    }
    EXPECT_FALSE(sync.pending());
    EXPECT_TRUE(mirror.equals(o.grid)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace nxtmap::protocol
