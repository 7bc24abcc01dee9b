// The house messages of exploring and scanning (Explore, GoTo, Scan, Readings): their bytes, their round trips,
// and every malformed payload refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"
#include "tests/protocol/PayloadRefusals.hpp"

namespace nxtmap::protocol {
namespace {

using test::Bytes;
using test::bytesOf;
using test::expectExactLength;
using test::expectRefused;

TEST(HouseMessages, ExploreIsAStrategyAndAConfineFlag) {
  Payload p;
  ASSERT_EQ(encodeExplore(ExploreMsg{ExploreStrategy::Propagation, true}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x00, 0x01}));
  ExploreMsg d;
  ASSERT_TRUE(decodeExplore(p.bytes, p.size, d));
  EXPECT_EQ(d.strategy, ExploreStrategy::Propagation);
  EXPECT_TRUE(d.confine);
  ASSERT_EQ(encodeExplore(ExploreMsg{ExploreStrategy::Frontier, false}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x01, 0x00}));
  expectExactLength(bytesOf(p), decodeExplore);
  expectRefused(bytesOf(p), {{"strategy 2", 0, 2}, {"flag bit 1", 1, 0x02}, {"flag bit 7", 1, 0x81}}, decodeExplore);
}

TEST(HouseMessages, GoToIsAGoalIdAndACell) {
  Payload p;
  ASSERT_EQ(encodeGoTo(GoToMsg{0x1234, Cell{-2, 300}}, p), 6u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x34, 0x12, 0xFE, 0xFF, 0x2C, 0x01}));
  GoToMsg d;
  ASSERT_TRUE(decodeGoTo(p.bytes, p.size, d));
  EXPECT_EQ(d.goalId, 0x1234);
  EXPECT_EQ(d.target, (Cell{-2, 300}));
  expectExactLength(bytesOf(p), decodeGoTo);
  expectRefused(bytesOf(p), {{"x 16638", 3, 0x40}, {"y 16428", 5, 0x40}}, decodeGoTo);
  expectRefused<GoToMsg>(
      GoToMsg{1, Cell{0, 0}},
      {{"x -16384", [](GoToMsg& m) { m.target.x = -16384; }}, {"y 16384", [](GoToMsg& m) { m.target.y = 16384; }}},
      encodeGoTo, decodeGoTo);
}

TEST(HouseMessages, ScanIsTheScansIdOneOrMore) {
  Payload p;
  ASSERT_EQ(encodeScan(ScanMsg{0x0102}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x02, 0x01}));
  ScanMsg d;
  ASSERT_TRUE(decodeScan(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 0x0102);
  expectExactLength(bytesOf(p), decodeScan);
  const Bytes zero = {0x00, 0x00};
  EXPECT_FALSE(decodeScan(zero.data(), zero.size(), d)) << "scan id 0";
  const Bytes top = {0xFF, 0xFF};
  EXPECT_TRUE(decodeScan(top.data(), top.size(), d));
}

ReadingsMsg fixedReadings() {
  ReadingsMsg m;
  m.scanId = 3;
  m.scanPose = Pose{Cell{-2, 7}, Dir::East};
  m.scan[0] = RangeReading{RangeStatus::Good, 42, 3};
  m.scan[1] = RangeReading{RangeStatus::NoEcho, 0, 3};
  m.scan[2] = RangeReading{RangeStatus::TooFar, 255, 10};
  m.scan[3] = RangeReading{RangeStatus::Inconsistent, 0, 10};
  return m;
}

TEST(HouseMessages, ReadingsCarryTheLastScan) {
  Payload p;
  ASSERT_EQ(encodeReadings(fixedReadings(), p), 15u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x03, 0x00,                                // scan id
                               0xFE, 0xFF, 0x07, 0x00, 0x01,              // its pose
                               42, 0x30, 0, 0x31, 255, 0xA3, 0, 0xA4}));  // Front, Right, Back, Left
  ReadingsMsg d;
  ASSERT_TRUE(decodeReadings(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 3);
  EXPECT_EQ(d.scanPose.cell, (Cell{-2, 7}));
  EXPECT_EQ(d.scanPose.heading, Dir::East);
  const ReadingsMsg m = fixedReadings();
  for (int i = 0; i < kSensorCount; ++i) {
    EXPECT_EQ(d.scan[i].status, m.scan[i].status) << i;
    EXPECT_EQ(d.scan[i].cm, m.scan[i].cm) << i;
    EXPECT_EQ(d.scan[i].samples, m.scan[i].samples) << i;
  }
  expectExactLength(bytesOf(p), decodeReadings);
  expectRefused(bytesOf(p),
                {{"scan pose x 16638", 3, 0x40},
                 {"scan pose heading 4", 6, 4},
                 {"front status 5", 8, 0x35},
                 {"front status 15", 8, 0x3F},
                 {"front samples 11", 8, 0xB0},
                 {"left status 7", 14, 0x47}},
                decodeReadings);
  // Readings the bytes cannot hold are not encoded.
  for (const int16_t cm : {-1, 256}) {
    ReadingsMsg bad = fixedReadings();
    bad.scan[2].cm = cm;
    EXPECT_EQ(encodeReadings(bad, p), 0u) << cm;
  }
  ReadingsMsg none;
  ASSERT_EQ(encodeReadings(none, p), 15u);  // no scan yet
  EXPECT_TRUE(decodeReadings(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 0);
}

}  // namespace
}  // namespace nxtmap::protocol
