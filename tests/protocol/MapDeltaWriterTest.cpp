// MapDeltaWriter's packed-run path (what MapSync uses) against the per-cell one.
#include <gtest/gtest.h>

#include <random>

#include "common/protocol/Messages.hpp"
#include "common/protocol/PackedDiff.hpp"

namespace nxtmap::protocol {
namespace {

TEST(MapDeltaWriter, PackedRunsAreTheSameBytesAsPerCellRuns) {
  std::mt19937 rng(21);
  uint8_t torus[64];
  for (uint8_t& b : torus) b = static_cast<uint8_t>(rng());
  MapDeltaHeader h;
  for (int trial = 0; trial < 200; ++trial) {
    Payload a, b;
    MapDeltaWriter wa(a, h), wb(b, h);
    while (true) {
      const uint8_t count = static_cast<uint8_t>(1 + rng() % kMaxRunCells);
      const uint32_t first = rng() % (4u * sizeof torus - count + 1u);  // inside the 256-cell torus
      uint8_t packed[(kMaxRunCells + 3) / 4];
      extractCells(torus, first, count, packed);
      const bool addedA = wa.addRun(static_cast<uint16_t>(first), count, [&](uint8_t k) {
        const uint32_t i = first + k;
        return static_cast<CellState>((torus[i >> 2] >> ((i & 3u) * 2u)) & 3u);
      });
      const bool addedB = wb.addPackedRun(static_cast<uint16_t>(first), count, packed);
      ASSERT_EQ(addedA, addedB);
      if (!addedA) break;
    }
    ASSERT_EQ(a.size, b.size);
    for (size_t i = 0; i < a.size; ++i) ASSERT_EQ(a.bytes[i], b.bytes[i]) << "byte " << i;
  }
}

TEST(MapDeltaWriter, CellsThatFitIsTheLargestRunThatFits) {
  MapDeltaHeader h;
  for (size_t limit = kMinDeltaPayload; limit <= kMaxPayload; ++limit) {
    Payload p;
    MapDeltaWriter w(p, h, limit);
    const uint8_t one = 0;
    for (int runs = 0; runs < 40; ++runs) {
      const size_t n = w.cellsThatFit();
      if (n > 0) {
        EXPECT_TRUE(w.fits(n)) << "limit " << limit << " runs " << runs;
      }
      EXPECT_FALSE(w.fits(n + 1)) << "limit " << limit << " runs " << runs;
      if (!w.addPackedRun(static_cast<uint16_t>(runs), 1, &one)) break;
    }
  }
}

}  // namespace
}  // namespace nxtmap::protocol
