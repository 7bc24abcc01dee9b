// The start's sweep through the simulator (sonar cone, range error, wheel noise): a robot set down off
// square in a room turned any way ends square to its walls before the explorer starts; with nothing in
// range it drives ahead and right until a wall is (or maps as set down).
// And the scene's own wall direction the squared run is scored in.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/mapping/MappingRun.hpp"
#include "host/mapping/RunTrace.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/SceneAxes.hpp"
#include "host/sim/WheelModel.hpp"
#include "host/worlds/SiteFiles.hpp"
#include "tests/mapping/TurnedRoom.hpp"

namespace nxtmap::mapping {
namespace {

using test::room;

// Degrees from `headingDeg` to the nearest of the scene's wall directions.
double offSquareDeg(double headingDeg, const sim::Scene& scene) {
  return std::fabs(std::remainder(headingDeg - sim::sceneAxesDeg(scene), 90.0));
}

struct Squared {
  double offBeforeDeg = 0.0, offAfterDeg = 0.0;
  bool found = false;
};

Squared squareIn(const sim::Site& site, const std::string& noise, uint64_t seed, bool square, double jitterDeg = 10) {
  RunConfig c;
  c.startPose = site.start;
  c.startJitterDeg = jitterDeg;
  c.noise = *sim::noiseProfileByName(noise);
  c.seed = seed;
  c.squareAtStart = square;
  MappingRun run(site, c);
  Squared s;
  s.offBeforeDeg = offSquareDeg(run.robot().headingDeg(), run.robot().scene());
  // The sweep's turns and readings until the pilot hands over to the explorer (nothing to do without it).
  for (int i = 0; square && i < 1000 && !run.pilot().squaring().finished(); ++i) run.step();
  EXPECT_EQ(run.pilot().squaring().finished(), square);
  s.offAfterDeg = offSquareDeg(run.robot().headingDeg(), run.robot().scene());
  s.found = run.pilot().squaring().result().found;
  return s;
}

TEST(StartSquaringRun, ARobotSetDownOffSquareEndsSquareToTheWalls) {
  struct Row {
    double roomDeg;
    const char* noise;
  };
  for (const Row row : {Row{0, "typical"}, Row{10, "typical"}, Row{-27, "nxt"}, Row{3, "nxt"}, Row{44, "nxt"}}) {
    const sim::Site site = room(row.roomDeg);
    EXPECT_NEAR(sim::sceneAxesDeg(*site.scene), std::remainder(-row.roomDeg, 90.0), 1e-6);
    double worst = 0.0, sum = 0.0, before = 0.0;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
      const Squared s = squareIn(site, row.noise, seed, true);
      EXPECT_TRUE(s.found) << row.roomDeg << " seed " << seed;
      worst = std::max(worst, s.offAfterDeg);
      sum += s.offAfterDeg;
      before = std::max(before, s.offBeforeDeg);
    }
    // Measured over seeds 1-30: mean 0.5-1.5 deg, worst 3.0 (nxt: backlash and turn errors in the sweep).
    EXPECT_LE(sum / 10, 2.0) << "room turned " << row.roomDeg << " deg, " << row.noise;
    EXPECT_LE(worst, 3.5) << "room turned " << row.roomDeg << " deg, " << row.noise;
    EXPECT_GE(before, 4.0) << "the jitter should have set the robot down off square";
  }
}

TEST(StartSquaringRun, WithoutTheSweepTheRobotStaysOffSquare) {
  const sim::Site site = room(10);
  double before = 0.0, after = 0.0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const Squared s = squareIn(site, "typical", seed, false);
    before += s.offBeforeDeg;
    after += s.offAfterDeg;
    EXPECT_FALSE(s.found);
  }
  EXPECT_NEAR(after, before, 1.0);
}

// The brick under `noise` set down up to 10 degrees off square (seed) at the start of `site`, run until the explorer
// starts: its sweeps (and approaches) only.
struct SweptStart {
  bool found = false;
  double offBeforeDeg = 0.0, offAfterDeg = 0.0;
  double northCm = 0.0, movedCm = 0.0;  // where it went: towards the start heading (north), and how far in all
  double turnedDeg = 0.0;               // heading after minus before (+ clockwise)
  double driftDegPerM = 0.0;            // the wheels' systematic drift (+ clockwise)
};
SweptStart sweepAtStart(const sim::Site& site, const char* noise, uint64_t seed) {
  RunConfig c;
  c.startPose = site.start;
  c.startJitterDeg = 10;
  c.noise = *sim::noiseProfileByName(noise);
  c.seed = seed;
  c.squareAtStart = true;
  c.robot = *sim::robotByName("brick");
  MappingRun run(site, c);
  SweptStart h;
  h.offBeforeDeg = offSquareDeg(run.robot().headingDeg(), run.robot().scene());
  const double heading0 = run.robot().headingDeg();
  h.driftDegPerM = run.robot().wheels().systematicDriftRadPerM() * 180.0 / 3.141592653589793;
  const double x0 = run.robot().xCm(), y0 = run.robot().yCm();
  for (int i = 0; i < 5000 && !run.pilot().explorerStarted(); ++i) run.step();
  EXPECT_TRUE(run.pilot().explorerStarted()) << noise << " seed " << seed;
  h.found = run.pilot().squaring().result().found;
  h.turnedDeg = std::remainder(run.robot().headingDeg() - heading0, 360.0);
  h.offAfterDeg = offSquareDeg(run.robot().headingDeg(), run.robot().scene());
  h.northCm = y0 - run.robot().yCm();
  h.movedCm = std::hypot(run.robot().xCm() - x0, run.robot().yCm() - y0);
  return h;
}

TEST(StartSquaringRun, InAHallWithNothingInReachTheRobotDrivesAheadThenRightUntilAWallIs) {
  // A 9 m square hall (turned 4 degrees), the robot in its middle: every wall 4.5 m away, no echo in any
  // direction. It drives 1.5 m ahead blind (PilotConfig::approachMaxCm) and sweeps again; then (blind to the
  // right of its start heading, or towards an echo once one is heard) until a sweep finds the walls, and squares.
  // Measured: 3.2 m north of its start, 1 m east, 0-2 degrees off the walls (5 before).
  const sim::Site site = room(4, 9.0, 9.0, 0.0, 0.0);
  for (const char* noise : {"typical", "nxt"}) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      const SweptStart h = sweepAtStart(site, noise, seed);
      EXPECT_TRUE(h.found) << noise << " seed " << seed;
      EXPECT_LE(h.offAfterDeg, 4.0) << noise << " seed " << seed;
      EXPECT_GE(h.northCm, 150.0) << noise << " seed " << seed;
    }
  }
}

TEST(StartSquaringRun, AHallTooLargeForEveryApproachIsMappedAsSetDown) {
  // A 20 m square hall: after its four blind approaches (1.5 m ahead, right, ahead, right: 4.2 m from its start)
  // the robot is still 7 m from every wall. No wall found, it maps as set down (its heading as the turns and the
  // drives' drift left it, where the approaches took it).
  const sim::Site site = room(7, 20.0, 20.0, 0.0, 0.0);
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const SweptStart h = sweepAtStart(site, "nxt", seed);
    EXPECT_FALSE(h.found) << seed;
    // Turned by the wheels' drift over the 6 m driven (nxt: 0.5 deg/m, 3 degrees) and the turns' random part (the
    // turns to and back from each approach cancel as the encoders count them, the sweeps end where they began): the
    // nxt turn error, 0.5 deg a quarter turn, over 5 sweeps and 8 approach turns is 2.7 deg (1 sigma); within 2 sigma.
    EXPECT_NEAR(h.turnedDeg, 6.0 * h.driftDegPerM, 5.5) << seed;
    EXPECT_NEAR(h.northCm, 300.0, 60.0) << seed;
    EXPECT_NEAR(h.movedCm, 424.0, 40.0) << seed;
  }
}

TEST(StartSquaringRun, WallsTooFarForTheSweepAreApproachedAndSweptAgain) {
  // 4.4 m square, turned 13 degrees, the robot in its middle: every wall 2.2 m away, beyond the 1.6 m a sweep
  // finds walls within (WallDirection::kFarCm), but in reach of an echo. It drives towards the nearest, then the
  // farthest up to 2.3 m (StartSquaring::approachEcho; as far
  // as PilotConfig::approachMaxCm), turns back to its heading and sweeps again (PilotConfig::approaches times at
  // most, not towards the same wall twice running): square before mapping. Sonars with a cone (`ideal` has one ray, whose dip beside one wall is too
  // narrow to trust: 4 of seeds 1-20 map as set down). Measured over seeds 1-20: worst 2.8 deg off (typical), 3.9
  // (nxt).
  const sim::Site site = room(13, 4.4, 4.4, 0.0, 0.0);
  for (const char* noise : {"typical", "nxt"}) {
    double sum = 0.0;
    for (uint64_t seed = 1; seed <= 10; ++seed) {
      const SweptStart h = sweepAtStart(site, noise, seed);
      EXPECT_TRUE(h.found) << noise << " seed " << seed;
      const double off = h.offAfterDeg;
      EXPECT_LE(off, 4.0) << noise << " seed " << seed;
      sum += off;
      const double moved = h.movedCm;
      EXPECT_GT(moved, 100.0) << noise << " seed " << seed;
      EXPECT_LE(moved, 2 * 155.0) << noise << " seed " << seed;
    }
    EXPECT_LE(sum / 10, 2.5) << noise;
  }
}

TEST(StartSquaringRun, InAClutteredRoomLaterApproachesGoToTheFarthestEcho) {
  // The published start-positions room from its middle (cell 11,11): at 20 cm cells 4.4 m across, its walls 2.2 m
  // away and blocks of 20-40 cm standing about. The nearest echoes are blocks: an approach to one finds no wall
  // beside it; the next approaches go to the farthest echo, the room's walls (StartSquaring::approachEcho).
  // Measured, nxt, seeds 1-10: a wall found and turned square to in 10 runs (3 when every approach went to the
  // nearest echo).
  const worlds::SiteLoad load =
      worlds::loadSite(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/start-positions.map", 20);
  ASSERT_TRUE(load.site && load.site->raster) << load.error;
  int found = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    RunConfig c;
    c.startPose = load.site->rasterStart(11, 11, 0.0);
    c.startJitterDeg = 10;
    c.noise = *sim::noiseProfileByName("nxt");
    c.seed = seed;
    c.robot = *sim::robotByName("brick");
    c.squareAtStart = true;
    MappingRun run(*load.site, c);
    for (int i = 0; i < 5000 && !run.pilot().explorerStarted(); ++i) run.step();
    ASSERT_TRUE(run.pilot().explorerStarted()) << seed;
    if (!run.pilot().squaring().result().found) continue;
    ++found;
    EXPECT_LE(offSquareDeg(run.robot().headingDeg(), run.robot().scene()), 6.0) << seed;
  }
  EXPECT_GE(found, 8);
}

TEST(StartSquaringRun, ARobotThatDroveOffAndFoundNoWallMapsFromWhereItStands) {
  // The published start-positions room from cell 5,14, at 20 cm cells a 4.4 m room with blocks in it, the brick
  // under nxt set down off square (seed 5): no sweep finds a straight wall; the robot drives
  // towards echoes between the sweeps, ends more than half a metre from where it was set down with no wall near
  // enough to snap to, and maps as set down from there. The grid it maps on (the truth it is scored against) is
  // laid where it stands: it starts in its believed cell. (Laid where it was set down, every cell it mapped was
  // scored shifted.)
  const worlds::SiteLoad load =
      worlds::loadSite(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/start-positions.map", 20);
  ASSERT_TRUE(load.site && load.site->raster) << load.error;
  RunConfig c;
  c.startPose = load.site->rasterStart(5, 14, 0.0);
  c.startJitterDeg = 10;
  c.noise = *sim::noiseProfileByName("nxt");
  c.seed = 5;
  c.robot = *sim::robotByName("brick");
  c.squareAtStart = true;
  MappingRun run(*load.site, c);
  const double x0 = run.robot().xCm(), y0 = run.robot().yCm();
  for (int i = 0; i < 5000 && !run.pilot().explorerStarted(); ++i) run.step();
  ASSERT_TRUE(run.pilot().explorerStarted());
  EXPECT_FALSE(run.pilot().squaring().result().found);
  EXPECT_GT(std::hypot(run.robot().xCm() - x0, run.robot().yCm() - y0), 50.0);
  const TracePose t = tracePose(run);
  EXPECT_FALSE(t.lost);
  EXPECT_LE(std::hypot(t.errXMm, t.errYMm), 100.0);
}

}  // namespace
}  // namespace nxtmap::mapping
