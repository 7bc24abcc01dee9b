// The brick's "nothing lost" bookkeeping: whatever is dropped, the PC's copy ends equal.
#include <gtest/gtest.h>

#include <ostream>
#include <random>

#include "common/protocol/MapSync.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol {
namespace {

using test::MirrorMap;
using test::OwnedGrid;

void setCell(RoomGrid& g, int x, int y, CellState s) {
  ASSERT_TRUE(g.set(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, s));
}

// Builds deltas until none is left, applying and acknowledging each.
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

TEST(MapSync, SendsChangedCellsAsRunsAndNothingWhenQuiet) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  EXPECT_EQ(drain(sync, mirror, seq, 0), 1);  // the epoch's announcement, empty
  EXPECT_TRUE(mirror.haveEpoch);
  for (int x = -5; x <= 10; ++x) setCell(o.grid, x, 3, CellState::Free);
  setCell(o.grid, 11, 3, CellState::Occupied);
  setCell(o.grid, 0, -20, CellState::Occupied);
  EXPECT_TRUE(sync.pending());
  Payload p;
  ASSERT_TRUE(sync.buildDelta(nextSeq(seq), 0, p));
  // The row from -5 to 11 wraps on the torus at x = 0: two runs; plus one single cell.
  MapDeltaReader r(p.bytes, p.size);
  ASSERT_TRUE(r.validate());
  EXPECT_EQ(r.header().runCount, 3);
  EXPECT_EQ(p.size, kDeltaHeaderSize + runBytes(5) + runBytes(12) + runBytes(1));
  ASSERT_TRUE(mirror.apply(p.bytes, p.size));
  sync.acknowledge(nextSeq(seq), 0, 0);
  EXPECT_TRUE(mirror.equals(o.grid));
  EXPECT_FALSE(sync.pending());
  EXPECT_FALSE(sync.buildDelta(7, 0, p));
  EXPECT_EQ(sync.inFlight(), 0);
}

// A window narrower than the grid leaves torus columns that unwrap to no cell of it. Changed cells
// on both sides of such a gap, closer than a run may bridge, must go in runs that stay inside the
// window: the PC refuses (and acknowledges) a delta naming a cell outside it, so the cells in it
// would be lost.
struct WindowGapRow {
  const char* what;
  int minX, maxX;  // the window's columns (cells set at both ends and next to them), row 5
};

class MapSyncWindowGap : public ::testing::TestWithParam<WindowGapRow> {};

TEST_P(MapSyncWindowGap, RunsStayInsideTheWindowAndTheCopyEndsEqual) {
  const WindowGapRow& r = GetParam();
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  for (int x : {r.minX, r.minX + 1, r.maxX - 1, r.maxX}) setCell(o.grid, x, 5, CellState::Free);
  setCell(o.grid, r.maxX, 6, CellState::Occupied);
  Payload p;
  seq = nextSeq(seq);
  ASSERT_TRUE(sync.buildDelta(seq, 0, p)) << r.what;
  MapDeltaReader reader(p.bytes, p.size);
  EXPECT_TRUE(reader.validate()) << r.what << ": a run names a cell outside the window";
  ASSERT_TRUE(mirror.apply(p.bytes, p.size)) << r.what;
  sync.acknowledge(seq, 0, 0);
  drain(sync, mirror, seq, 0);
  EXPECT_TRUE(mirror.equals(o.grid)) << r.what;
}

void PrintTo(const WindowGapRow& r, std::ostream* os) { *os << r.what; }

INSTANTIATE_TEST_SUITE_P(Rows, MapSyncWindowGap,
                         ::testing::Values(WindowGapRow{"60 wide across the wrap: a 4-column gap", -3, 56},
                                           WindowGapRow{"63 wide: a 1-column gap", -10, 52},
                                           WindowGapRow{"57 wide: a 7-column gap, the longest a run bridges", -20, 36},
                                           WindowGapRow{"56 wide: an 8-column gap, never bridged", -20, 35},
                                           WindowGapRow{"the whole 64 columns: no gap", -32, 31},
                                           WindowGapRow{"60 wide, not wrapped", 2, 61}));

TEST(MapSync, ALostDeltaIsSentAgainAfterTheTimeoutWithCurrentStates) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  setCell(o.grid, 1, 1, CellState::Free);
  setCell(o.grid, 2, 1, CellState::Free);
  Payload lost;
  ASSERT_TRUE(sync.buildDelta(100, 1000, lost));  // never arrives
  EXPECT_FALSE(sync.pending());
  setCell(o.grid, 2, 1, CellState::Occupied);  // changes again while in flight
  Payload p;
  ASSERT_TRUE(sync.buildDelta(101, 1010, p));  // carries only (2,1)
  ASSERT_TRUE(mirror.apply(p.bytes, p.size));
  sync.acknowledge(101, 0, 1050);  // round trips of 0 (drain) and 40 ms: a timeout well below 400 ms
  const uint32_t rto = sync.retransmitTimeoutMs();
  EXPECT_GE(rto, MapSync::kMinRtoMs);
  EXPECT_LT(rto, 400u);
  EXPECT_FALSE(mirror.equals(o.grid));  // (1,1) is missing
  EXPECT_EQ(sync.expire(1000 + rto - 1), 0);
  EXPECT_EQ(sync.expire(1000 + rto), 1);
  EXPECT_TRUE(sync.pending());
  drain(sync, mirror, seq, 1500);
  EXPECT_TRUE(mirror.equals(o.grid));
  EXPECT_EQ(mirror.cells.at({2, 1}), CellState::Occupied);
}

TEST(MapSync, AtMostSixDeltasAreInFlightAndAcksFreeThem) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  for (int y = 0; y < 64; y += 2) {
    for (int x = 0; x < 64; x += 2) setCell(o.grid, x, y, CellState::Free);  // 32 rows of 63-cell runs: 7 deltas
  }
  Payload p;
  uint16_t seq = 0;
  for (int i = 0; i < MapSync::kSlots; ++i) ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  EXPECT_FALSE(sync.buildDelta(nextSeq(seq), 0, p));
  EXPECT_EQ(sync.inFlight(), 6);
  sync.acknowledge(6, 0x0001, 10);  // 6 and 5
  EXPECT_EQ(sync.inFlight(), 4);
  sync.acknowledge(6, 0x001E, 10);  // 4, 3, 2 and 1 through the mask
  EXPECT_EQ(sync.inFlight(), 0);
}

TEST(MapSync, TheTimeoutFollowsTheRoundTrip) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 1000);
  EXPECT_EQ(sync.retransmitTimeoutMs(), 1000u);  // nothing measured yet: the configured time
  Payload p;
  uint16_t seq = 0;
  uint32_t now = 0;
  for (int i = 0; i < 40; ++i) {  // a steady 100 ms round trip
    setCell(o.grid, i % 30, i / 30, CellState::Free);
    ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), now, p));
    now += 100;
    sync.acknowledge(seq, 0, now);
  }
  EXPECT_NEAR(static_cast<double>(sync.retransmitTimeoutMs()), 2 * 100 + MapSync::kRtoMarginMs, 10);
  for (int i = 0; i < 60; ++i) {  // then a fast link: the timeout comes down, never below the floor
    setCell(o.grid, i % 30, 3 + i / 30, CellState::Occupied);
    ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), now, p));
    sync.acknowledge(seq, 0, now);
  }
  EXPECT_EQ(sync.retransmitTimeoutMs(), MapSync::kMinRtoMs);
}

TEST(MapSync, LinkLossSendsInFlightCellsAgain) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  drain(sync, mirror, seq, 0);
  setCell(o.grid, 5, 5, CellState::Occupied);
  Payload p;
  ASSERT_TRUE(sync.buildDelta(seq = nextSeq(seq), 0, p));
  sync.linkLost();
  EXPECT_EQ(sync.inFlight(), 0);
  drain(sync, mirror, seq, 0);
  EXPECT_TRUE(mirror.equals(o.grid));
}

TEST(MapSync, RestructuringStartsANewEpochAndTheCopyFollows) {
  OwnedGrid<> o;
  MapSync sync(o.grid, o.shadow, 400);
  MirrorMap mirror;
  uint16_t seq = 0;
  for (int x = -3; x <= 3; ++x) setCell(o.grid, x, -2, CellState::Occupied);
  setCell(o.grid, 0, 0, CellState::Free);
  drain(sync, mirror, seq, 0);
  ASSERT_TRUE(mirror.equals(o.grid));
  const uint16_t before = sync.epoch();
  o.grid.restructure();  // (-3, -2) becomes (0, 0): the window no longer contains the old one
  drain(sync, mirror, seq, 0);
  EXPECT_NE(sync.epoch(), before);
  EXPECT_EQ(mirror.epoch, sync.epoch());
  EXPECT_TRUE(mirror.equals(o.grid));
  EXPECT_EQ(mirror.cells.count({0, 0}), 1u);
  EXPECT_EQ(mirror.cells.count({-3, -2}), 0u);
}

// Random grids, random losses and timeouts: once the grid is quiet and the link works, equal.
TEST(MapSync, RandomChangesAndLossesAlwaysConverge) {
  for (uint32_t seed = 1; seed <= 30; ++seed) {
    std::mt19937 rng(seed);
    OwnedGrid<> o;
    MapSync sync(o.grid, o.shadow, 100);
    MirrorMap mirror;
    uint16_t seq = 0;
    uint32_t now = 0;
    for (int step = 0; step < 400; ++step) {
      now += 10;
      const int changes = static_cast<int>(rng() % 6);
      for (int k = 0; k < changes; ++k) {
        const int x = static_cast<int>(rng() % 50) - 25, y = static_cast<int>(rng() % 50) - 25;
        ASSERT_TRUE(
            o.grid.set(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, static_cast<CellState>(1 + rng() % 2)));
      }
      sync.expire(now);
      Payload p;
      if (sync.buildDelta(seq = nextSeq(seq), now, p)) {
        if (rng() % 4 != 0) {  // a quarter of the deltas are lost
          ASSERT_TRUE(mirror.apply(p.bytes, p.size));
          if (rng() % 3 != 0) sync.acknowledge(seq, 0, now + 5);  // and a third of the acks
        }
      }
      if (rng() % 97 == 0) sync.linkLost();
    }
    for (int i = 0; i < 200 && (sync.pending() || sync.inFlight() > 0); ++i) {
      now += 200;
      sync.expire(now);
      drain(sync, mirror, seq, now);
    }
    EXPECT_TRUE(mirror.equals(o.grid)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace nxtmap::protocol
