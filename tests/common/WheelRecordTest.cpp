// WheelRecord: the learnt wheels as the words the brick keeps in flash. Round trips for the wheels a robot may
// learn; an erased page, a torn or altered record, another version and wheels no robot has decode to nothing
// and leave the caller's calibration as it was.
#include "common/motion/WheelRecord.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace nxtmap {
namespace {

using Words = uint32_t[WheelRecord::kWords];

WheelCalibration wheels(int32_t drift, int32_t turn, int64_t driftVar, int64_t turnVar) {
  WheelCalibration w;
  w.driftUradPerM = drift;
  w.turnPpm = turn;
  w.driftVariance = driftVar;
  w.turnVariance = turnVar;
  return w;
}

void expectSame(const WheelCalibration& a, const WheelCalibration& b) {
  EXPECT_EQ(a.driftUradPerM, b.driftUradPerM);
  EXPECT_EQ(a.turnPpm, b.turnPpm);
  EXPECT_EQ(a.driftVariance, b.driftVariance);
  EXPECT_EQ(a.turnVariance, b.turnVariance);
  EXPECT_TRUE(WheelRecord::same(a, b));
}

TEST(WheelRecord, WhatRobotsLearnComesBackWordForWord) {
  const std::vector<WheelCalibration> table = {
      WheelCalibration{},                                                // nothing learnt yet: the defaults
      wheels(-33510, 17800, 4000000, 250000),                            // drift -1.92 deg/m, turns +1.78 %
      wheels(199999, -99999, 1, 1),                                      // the edges of what wheels do, known exactly
      wheels(-199999, 99999, 35000LL * 35000 * 4, 20000LL * 20000 * 9),  // the variances' high words used
  };
  for (const WheelCalibration& w : table) {
    Words words;
    WheelRecord::encode(w, words);
    EXPECT_EQ(words[0], WheelRecord::kMagic);
    EXPECT_EQ(words[3], WheelRecord::kVersion);
    WheelCalibration back = wheels(1, 2, 3, 4);
    ASSERT_TRUE(WheelRecord::decode(words, back)) << w.driftUradPerM;
    expectSame(back, w);
  }
}

TEST(WheelRecord, AnErasedPageHoldsNothing) {
  Words erased;
  for (uint32_t& word : erased) word = 0xFFFFFFFFu;
  WheelCalibration w = wheels(5, 6, 7, 8);
  EXPECT_FALSE(WheelRecord::decode(erased, w));
  expectSame(w, wheels(5, 6, 7, 8));
}

TEST(WheelRecord, AnyWordChangedOrTornOffIsRefused) {
  Words good;
  WheelRecord::encode(wheels(-33510, 17800, 4000000, 250000), good);
  for (int i = 0; i < WheelRecord::kWords; ++i) {
    for (const uint32_t flip : {1u, 0x80000000u, 0x00010000u}) {
      Words bad;
      for (int k = 0; k < WheelRecord::kWords; ++k) bad[k] = good[k];
      bad[i] ^= flip;
      WheelCalibration w;
      EXPECT_FALSE(WheelRecord::decode(bad, w)) << "word " << i << " flipped by " << flip;
    }
    Words torn;  // a power cut while programming: the words from i on still erased
    for (int k = 0; k < WheelRecord::kWords; ++k) torn[k] = k < i ? good[k] : 0xFFFFFFFFu;
    WheelCalibration w;
    EXPECT_FALSE(WheelRecord::decode(torn, w)) << "torn at word " << i;
  }
}

TEST(WheelRecord, AnotherVersionOrWheelsNoRobotHasAreRefusedEvenWithTheirCheckRight) {
  const struct {
    int word;
    uint32_t value;
    const char* what;
  } table[] = {
      {3, 2, "version 2"},
      {1, 200000, "drift 200 mrad/m"},
      {1, static_cast<uint32_t>(-200000), "drift -200 mrad/m"},
      {1, 0x80000000u, "drift the least int32"},
      {2, 100000, "turns 10 % off"},
      {2, static_cast<uint32_t>(-100000), "turns -10 % off"},
      {4, 0, "drift variance 0"},
      {5, 0x80000000u, "drift variance negative"},
      {6, 0, "turn variance 0"},
      {7, 0xFFFFFFFFu, "turn variance negative"},
  };
  for (const auto& row : table) {
    Words words;
    WheelRecord::encode(wheels(1000, 2000, 0, 0), words);
    words[4] = 5;  // variances 5 and 6 unless the row changes them
    words[6] = 6;
    words[row.word] = row.value;
    words[WheelRecord::kWords - 1] = WheelRecord::checkOf(words);
    WheelCalibration w;
    EXPECT_FALSE(WheelRecord::decode(words, w)) << row.what;
  }
}

TEST(WheelRecord, SameComparesEveryField) {
  const WheelCalibration base = wheels(10, 20, 30, 40);
  EXPECT_TRUE(WheelRecord::same(base, wheels(10, 20, 30, 40)));
  EXPECT_FALSE(WheelRecord::same(base, wheels(11, 20, 30, 40)));
  EXPECT_FALSE(WheelRecord::same(base, wheels(10, 21, 30, 40)));
  EXPECT_FALSE(WheelRecord::same(base, wheels(10, 20, 31, 40)));
  EXPECT_FALSE(WheelRecord::same(base, wheels(10, 20, 30, 41)));
}

}  // namespace
}  // namespace nxtmap
