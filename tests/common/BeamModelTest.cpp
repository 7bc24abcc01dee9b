// BeamModel against values computed by hand (a calculator, in reals) from the documented mixture with the
// default (nxt) parameters: w_hit 0.9, w_short 0.05, w_max 0.03, w_rand 0.02, sigma 2 cm, short mean 30 cm,
// reading = 0.9757 true + 1.9 cm rounded to the mm (the model's biasMm 19), echoes sure to 160 cm and gone at
// 260 cm, wild readings over 0..254 cm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "common/sensing/BeamModel.hpp"

namespace nxtmap {
namespace {

constexpr int16_t kNoEcho = BeamModel::kNoEcho;
constexpr int16_t kNothing = BeamModel::kNothing;

double perMille(uint32_t q24) { return q24 * 1000.0 / BeamModel::kOne; }

TEST(BeamModel, ProbabilitiesAndCostsFromTable) {
  const BeamModel model;
  const struct {
    const char* name;
    int16_t z, trueCm;
    double perMille;  // p(z | z*) by hand
    int cost;         // -8 ln p, rounded
  } table[] = {
      // 0.9 / (2 sqrt(2 pi)) e^(-0.5^2 / 8) + 0.02 / 255: the hit's peak (the reading expected: 99.5 cm)
      {"z half a cm below the expected reading", 99, 100, 174.143, 14},
      {"z half a cm past it", 100, 100, 174.079, 14},
      // 3.5 cm = 1.75 sigma off: 0.17952 e^(-3.5^2 / 8) + 0.02 / 255
      {"z 1.75 sigma off", 103, 100, 38.903, 26},
      // 6.5 cm = 3.25 sigma off: the gaussian has fallen to the floor's order
      {"z 3.25 sigma off", 106, 100, 0.992, 55},
      // nearer: 0.05 e^(-20/30) / 30 / (1 - e^(-99.5/30)) + the random floor
      {"a short reading", 20, 100, 0.966, 56},
      {"farther than the target: only the random floor", 150, 100, 0.078, 76},
      // no echo: w_max + w_hit (1 - echo(z*)), echo(200) = 0.6, echo(220) = 0.4
      {"no echo, the target near", kNoEcho, 50, 30.0, 28},
      {"no echo, the target far", kNoEcho, 200, 390.0, 8},
      {"no echo, the target farther", kNoEcho, 220, 570.0, 5},
      {"no echo, nothing in reach", kNoEcho, kNothing, 930.0, 1},
      {"an echo with nothing in reach: short + random", 60, kNothing, 0.304, 65},
      {"a near target (6 cm: 7.8 expected)", 8, 6, 178.707, 14},
  };
  for (const auto& t : table) {
    const uint32_t p = model.probability(t.z, t.trueCm);
    EXPECT_NEAR(perMille(p), t.perMille, t.perMille * 0.01 + 0.002) << t.name;
    EXPECT_NEAR(model.cost(t.z, t.trueCm), t.cost, 1) << t.name;
  }
}

TEST(BeamModel, MixtureSumsToOne) {
  const BeamModel model;
  // Over every reading 0..254 and "no echo": 1 up to the discretisation of the hit (whole cm) and of the short
  // part (0.1 % by hand for these ranges).
  for (const int16_t trueCm : {int16_t{30}, int16_t{100}, int16_t{220}, kNothing}) {
    uint64_t sum = model.probability(kNoEcho, trueCm);
    for (int16_t z = 0; z < kNoEcho; ++z) sum += model.probability(z, trueCm);
    EXPECT_NEAR(static_cast<double>(sum) / BeamModel::kOne, 1.0, 0.005) << trueCm;
  }
}

TEST(BeamModel, ExpectedReadingAndEchoProbability) {
  const BeamModel model;
  EXPECT_EQ(model.expectedReadingMm(0), 19);
  EXPECT_EQ(model.expectedReadingMm(100), 995);  // 975.7 + 18.8 mm, to the mm
  EXPECT_EQ(model.expectedReadingMm(250), 2458);
  EXPECT_EQ(model.echoPerMille(160), 1000);
  EXPECT_EQ(model.echoPerMille(210), 500);
  EXPECT_EQ(model.echoPerMille(260), 0);
  EXPECT_EQ(model.echoPerMille(kNothing), 0);
}

TEST(BeamModel, BestCostIsTheLowestOverTrueRanges) {
  const BeamModel model;
  for (const int16_t z : {int16_t{8}, int16_t{40}, int16_t{99}, int16_t{150}, kNoEcho}) {
    uint8_t lowest = model.cost(z, kNothing);
    for (int16_t t = 0; t < 300; ++t) {
      const uint8_t c = model.cost(z, t);
      if (c < lowest) lowest = c;
    }
    EXPECT_EQ(model.bestCost(z), lowest) << z;
  }
}

TEST(BeamModel, ExpAndCostAreInverse) {
  EXPECT_EQ(BeamModel::expQ24(0), BeamModel::kOne);
  EXPECT_EQ(BeamModel::expQ24(8), 6171993u);  // e^-1
  EXPECT_EQ(BeamModel::expQ24(BeamModel::kMaxExpCost + 1), 0u);
  for (int32_t n = 0; n <= 100; ++n) {
    EXPECT_NEAR(BeamModel::expQ24(n), std::exp(-n / 8.0) * BeamModel::kOne, 2.0 + BeamModel::expQ24(n) * 1e-4);
    EXPECT_EQ(BeamModel::costOf(BeamModel::expQ24(n)), n);
  }
  EXPECT_EQ(BeamModel::costOf(0), BeamModel::kMaxCost);
  EXPECT_EQ(BeamModel::costOf(BeamModel::kOne / 2), 6);  // 8 ln 2 = 5.5: rounds to the nearer
}

}  // namespace
}  // namespace nxtmap
