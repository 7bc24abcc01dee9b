// SonarModel against the measurements it was built from (nxt-sonar-and-odometry.md), as tables.
#include "host/sim/SonarModel.hpp"

#include "tests/sim/SonarScenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace nxtmap::sim {
namespace {

using test::flatWall;
using test::kReach;
using test::nxtClean;
using test::openRoom;
using test::pingWall;

constexpr double kPi = 3.14159265358979323846;

TEST(SonarModel, LinearFitOnAFlatWallFrom8To64CmReproducesJasonatwood) {
  const Scene scene = flatWall(Surface::Hard);
  std::mt19937_64 rng(7);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k <= 112; ++k) {
    const double d = 8.0 + 0.5 * k;
    for (int p = 0; p < 40; ++p) {
      const double x = 3.0 * p + 0.3 * (k % 3);
      const int r = pingWall(scene, nxtClean(), x, d, 0.0, 7, rng);
      ASSERT_NE(r, SonarModel::kNoEcho) << d;
      n += 1;
      sx += d;
      sy += r;
      sxx += d * d;
      sxy += d * r;
    }
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double offset = (sy - slope * sx) / n;
  EXPECT_NEAR(slope, 0.9757, 0.01);
  EXPECT_NEAR(offset, 1.88, 0.3);
}

struct NearRow {
  NearField mode;
  double distanceCm;
  bool echo;
  double meanCm;  // expected mean reading when echo
};

TEST(SonarModel, NearFieldMasksOrReadsHigh) {
  const Scene scene = flatWall(Surface::Hard);
  const std::vector<NearRow> rows = {
      {NearField::NoEcho, 4.0, false, 0},     {NearField::NoEcho, 6.5, false, 0},
      {NearField::NoEcho, 9.0, true, 10.66},  // 0.9757 * 9 + 1.88: the linear part
      {NearField::ReadsHigh, 5.0, true, 7.0}, {NearField::ReadsHigh, 3.5, true, 5.5},
      {NearField::ReadsHigh, 2.0, false, 0},
  };
  for (const NearRow& row : rows) {
    SonarNoise noise = nxtClean();
    noise.nearFieldMode = row.mode;
    std::mt19937_64 rng(11);
    double sum = 0;
    int echoes = 0;
    for (int p = 0; p < 200; ++p) {
      const int r = pingWall(scene, noise, 2.0 * p, row.distanceCm, 0.0, 11, rng);
      if (r != SonarModel::kNoEcho) {
        sum += r;
        ++echoes;
      }
    }
    const std::string what = std::to_string(static_cast<int>(row.mode)) + " at " + std::to_string(row.distanceCm);
    EXPECT_EQ(echoes, row.echo ? 200 : 0) << what;
    if (row.echo) {
      EXPECT_NEAR(sum / echoes, row.meanCm, 0.3) << what;
    }
  }
}

TEST(SonarModel, WildReadingsAreRareZerosNoEchoesAndShortOnes) {
  const Scene scene = flatWall(Surface::Hard);
  std::mt19937_64 rng(23);
  int wild = 0;
  const int pings = 4000;
  for (int p = 0; p < pings; ++p) {
    const int r = pingWall(scene, sonarPreset("nxt"), 0.3 * p - 600.0, 40.0, 0.0, 23, rng);
    if (r < 36 || r > 44) ++wild;  // 0.9757 * 40 + 1.88 = 40.9, fixed error sigma 1 cm
  }
  EXPECT_GT(wild, pings * 0.01);  // nxt: 2 % wild, two thirds of them far from the truth
  EXPECT_LT(wild, pings * 0.025);
}

struct IncidenceRow {
  double turnDeg;  // the sensor's axis against the wall's normal
  double minLoss, maxLoss;
};

TEST(SonarModel, EchoLossRisesWithIncidenceOnAHardWall) {
  const Scene scene = flatWall(Surface::Hard);
  // nxt: loss from 35 degrees, 0.9 at 60 degrees: 0, 0, 0.18, 0.9 (one wall: no phantom path).
  const std::vector<IncidenceRow> rows = {{0, 0, 0}, {20, 0, 0}, {40, 0.1, 0.27}, {60, 0.84, 0.96}};
  for (const IncidenceRow& row : rows) {
    std::mt19937_64 rng(13);
    int lost = 0;
    const int poses = 500;
    for (int p = 0; p < poses; ++p) {
      if (pingWall(scene, nxtClean(), 2.0 * p - 500.0, 50.0, row.turnDeg, 13, rng) == SonarModel::kNoEcho) ++lost;
    }
    EXPECT_GE(lost, row.minLoss * poses) << row.turnDeg;
    EXPECT_LE(lost, row.maxLoss * poses) << row.turnDeg;
  }
}

TEST(SonarModel, ALostObliqueEchoMayReturnLongAfterASecondBounce) {
  // A corner: the sensor at (0, 50) faces north-east towards the wall y = 0; a second wall stands at x = 100.
  Scene scene = openRoom();
  scene.addWall(Edge{Vec2(-500, 0), Vec2(100, 0), Surface::Hard});
  scene.addWall(Edge{Vec2(100, 0), Vec2(100, 500), Surface::Hard});
  scene.finish();
  for (const double phantomProb : {0.0, 1.0}) {
    SonarNoise noise = nxtClean();
    noise.incidenceLossFullDeg = 40.0;  // every echo off y = 0 lost at 45 degrees
    noise.incidenceLossMaxProb = 1.0;
    noise.phantomProb = phantomProb;
    std::mt19937_64 rng(17);
    const int r = pingWall(scene, noise, 0.0, 50.0, 45.0, 17, rng);
    if (phantomProb == 0.0) {
      EXPECT_EQ(r, SonarModel::kNoEcho);
    } else {
      EXPECT_GT(r, 110);  // the straight way to either wall is at most 100 cm; the axis meets y = 0 at 71
      EXPECT_LT(r, 145);  // the axis' own bounce path is 141 cm
    }
  }
}

struct TargetRow {
  Surface surface;
  double distanceCm;
  double minEcho, maxEcho;  // fraction of poses with an echo
};

TEST(SonarModel, SoftAndThinTargetsAreWeakerThanHardOnes) {
  // nxt: soft echoes 0.7 within 96 cm, none past 156; thin 0.5 within 64 cm, none past 104; hard always
  // within 160, 0.6 at 200, 0.1 at 250.
  const std::vector<TargetRow> rows = {
      {Surface::Hard, 30, 1, 1},  {Surface::Soft, 30, 0.6, 0.8},   {Surface::Thin, 30, 0.4, 0.6},
      {Surface::Hard, 150, 1, 1}, {Surface::Soft, 150, 0.0, 0.15}, {Surface::Thin, 90, 0.1, 0.3},
      {Surface::Thin, 110, 0, 0}, {Surface::Hard, 200, 0.5, 0.7},  {Surface::Hard, 250, 0.03, 0.18},
  };
  for (const TargetRow& row : rows) {
    Scene scene = openRoom();
    if (row.surface == Surface::Thin) {
      scene.addDisc(Disc{Vec2(0, 0), 1.25, Surface::Thin});  // a table leg, met from all round
    } else {
      scene.addWall(Edge{Vec2(-800, 0), Vec2(800, 0), row.surface});
    }
    scene.finish();
    std::mt19937_64 rng(19);
    int echoes = 0;
    const int poses = 400;
    for (int p = 0; p < poses; ++p) {
      Vec2 face(3.0 * p - 600.0, row.distanceCm);
      double axis = 0.0;
      if (row.surface == Surface::Thin) {
        axis = 0.9 * p;  // facing the leg's centre from compass axis + 180
        const double rad = (axis + 180.0) * kPi / 180.0;
        face = (row.distanceCm + 1.25) * Vec2(std::sin(rad), -std::cos(rad));
      }
      SonarModel model(nxtClean(), kReach, 19);
      if (model.ping(scene, face, axis, 0, 0.0, false, rng) != SonarModel::kNoEcho) ++echoes;
    }
    const std::string what = std::string(surfaceName(row.surface)) + " at " + std::to_string(row.distanceCm);
    EXPECT_GE(echoes, row.minEcho * poses) << what;
    EXPECT_LE(echoes, row.maxEcho * poses) << what;
  }
}

struct BeamRow {
  double rangeCm, offAxisDeg;
  bool seen;
};

TEST(SonarModel, BeamIsNarrowCloseWidestBetweenAndNarrowAtTheLimit) {
  const SonarNoise nxt = sonarPreset("nxt");
  SonarNoise beamOnly;
  beamOnly.coneHalfAngleDeg = nxt.coneHalfAngleDeg;
  beamOnly.coneWideDeg = nxt.coneWideDeg;
  beamOnly.coneWideAtCm = nxt.coneWideAtCm;
  beamOnly.coneFarDeg = nxt.coneFarDeg;
  beamOnly.specularAngleDeg = 90.0;
  // A thin pole (0.3 cm: met by one ray only) on the 11.25 degree ray; nxt's half-angle is 10 degrees at
  // 0 cm, 15 at 60 cm, 5 at 255 cm: 11.25 is inside it from 15 to 133 cm.
  const std::vector<BeamRow> rows = {
      {8, 11.25, false}, {30, 11.25, true}, {120, 11.25, true}, {150, 11.25, false}, {200, 0, true}};
  for (const BeamRow& row : rows) {
    Scene scene = openRoom();
    const double rad = row.offAxisDeg * kPi / 180.0;
    scene.addDisc(Disc{Vec2(row.rangeCm * std::sin(rad), -row.rangeCm * std::cos(rad)), 0.3, Surface::Hard});
    scene.finish();
    SonarModel model(beamOnly, kReach, 1);
    std::mt19937_64 rng(1);
    const int r = model.ping(scene, Vec2(0, 0), 0.0, 0, 0.0, false, rng);
    EXPECT_EQ(r != SonarModel::kNoEcho, row.seen) << row.rangeCm << " cm, " << row.offAxisDeg << " deg";
  }
}

struct Shot {
  int sensor;
  double atMs;
  bool othersFiring;
};

struct CrosstalkRow {
  std::string what;
  std::string preset;
  std::vector<Shot> shots;  // the last one is inspected
  double minShare, maxShare;
};

TEST(SonarModel, CrossTalkOnlyWhenTwoSensorsPingWithinTheEchoWindow) {
  const Scene scene = flatWall(Surface::Hard);  // every sensor 120 cm from the wall: a cross-talk reads 3..50
  const double p = sonarPreset("nxt").crosstalkProb;
  const std::vector<CrosstalkRow> rows = {
      {"one sensor, pings 1 ms apart", "nxt", {{0, 0, false}, {0, 1, false}, {0, 2, false}}, 0, 0},
      {"one sensor said to fire with others", "nxt", {{0, 0, true}}, p - 0.1, p + 0.1},
      {"two sensors at the same moment", "nxt", {{0, 0, false}, {1, 0, false}}, p - 0.1, p + 0.1},
      {"two sensors 30 ms apart", "nxt", {{2, 0, false}, {3, 30, false}}, p - 0.1, p + 0.1},
      {"the firmware's sequence, kPingMs apart",
       "nxt",
       {{0, 0, false}, {1, SonarModel::kPingMs, false}, {2, 2 * SonarModel::kPingMs, false}},
       0,
       0},
      {"typical: two sensors at the same moment, not said to fire together",
       "typical",
       {{0, 0, false}, {1, 0, false}},
       0,
       0},
  };
  for (const CrosstalkRow& row : rows) {
    SonarNoise noise = sonarPreset(row.preset);
    noise.wildProb = 0.0;
    noise.dropoutProb = 0.0;
    int crossed = 0;
    const int trials = 400;
    for (int t = 0; t < trials; ++t) {
      SonarModel model(noise, kReach, static_cast<uint64_t>(t));
      std::mt19937_64 rng(static_cast<uint64_t>(t));
      int last = 0;
      for (const Shot& s : row.shots)
        last = model.ping(scene, Vec2(t, 120), 0.0, s.sensor, s.atMs, s.othersFiring, rng);
      if (last <= 50) ++crossed;
    }
    EXPECT_GE(crossed, row.minShare * trials) << row.what;
    EXPECT_LE(crossed, row.maxShare * trials) << row.what;
  }
}

TEST(SonarModel, IdealReadsTheRoundedDistanceAndDrawsNothing) {
  const Scene scene = flatWall(Surface::Hard);
  for (const double d : {4.0, 37.4, 37.6, 254.0}) {
    SonarModel model(sonarPreset("ideal"), kReach, 1);
    std::mt19937_64 rng(9);
    const std::mt19937_64 before = rng;
    EXPECT_EQ(model.ping(scene, Vec2(0, d), 0.0, 1, 0.0, true, rng), std::lround(d));
    EXPECT_EQ(rng, before);
  }
}

}  // namespace
}  // namespace nxtmap::sim
