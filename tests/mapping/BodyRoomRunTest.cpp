// The brick's body (16 x 18 cm, sweeping 12 cm when it turns) in 20 cm cells, through the simulator: set
// down in a corner it is moved to where it can turn, it turns only where the four cells around it are known
// free, and once square to the walls it lays its cells' edges on the nearest walls.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/mapping/MapScore.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "tests/mapping/WorldText.hpp"

namespace nxtmap::mapping {
namespace {

// A 3.3 x 2.5 m room with a table-sized block in it, turned `turnDeg`; the start at (x, y) m facing north.
sim::Site room(double turnDeg, double x, double y) {
  const std::string text =
      "nxtmap_world: 1\noutline:\n  polygon: [[-1.65, -1.25], [1.65, -1.25], [1.65, 1.25], [-1.65, 1.25]]\n"
      "obstacles:\n  - polygon: [[0.2, 0.1], [0.75, 0.1], [0.75, 0.5], [0.2, 0.5]]\n"
      "start: {x: " +
      std::to_string(x) + ", y: " + std::to_string(y) +
      ", yaw: 90}\ntransform: {rotate_deg: " + std::to_string(turnDeg) + "}\n";
  return test::siteFromWorldText(text);
}

RunConfig brickConfig(const sim::Site& site, const std::string& noise, uint64_t seed, double jitterDeg) {
  RunConfig c;
  c.startPose = site.start;
  c.startJitterDeg = jitterDeg;
  c.robot = *sim::robotByName("brick");
  c.noise = *sim::noiseProfileByName(noise);
  c.seed = seed;
  c.squareAtStart = true;
  c.strategy = Strategy::Frontier;
  return c;
}

TEST(BodyRoomRun, SetDownInACornerTheBrickMapsTheRoomTurningOnlyWhereItHasRoom) {
  // A room of 20 cm cells with walls on the cells' edges and two blocks; asked to start in the corner
  // cell (1, 8), 10 cm from two walls, where the body cannot turn. Before the body was planned for, the
  // brick stalled its first turn there and mapped 3 % of the room.
  const sim::World world =
      sim::World::fromRows({"############", "#..........#", "#..........#", "#...##.....#", "#...##.....#",
                            "#..........#", "#.......#..#", "#..........#", "#..........#", "############"},
                           0.20);
  for (const char* noise : {"ideal", "typical"}) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      RunConfig c;
      c.startCol = 1;
      c.startRow = 8;
      c.robot = *sim::robotByName("brick");
      c.noise = *sim::noiseProfileByName(noise);
      c.seed = seed;
      c.strategy = Strategy::Frontier;
      c.squareAtStart = true;  // as the brick does (--square auto): its cells' edges laid on the walls
      MappingRun run(world, c);
      EXPECT_NEAR(run.startMovedCm(), 20.0 * std::sqrt(2.0), 1e-9) << noise << " seed " << seed;
      run.runToEnd();
      const MapScore s = scoreRun(run);
      EXPECT_FALSE(s.lost) << noise << " seed " << seed;
      EXPECT_GE(s.detectedPct(), 95.0) << noise << " seed " << seed;
      EXPECT_LE(s.wrongCells, 3) << noise << " seed " << seed;
    }
  }
}

// The distance (cm) from the robot's centre to the first solid thing along compass `deg`.
double wallAt(const MappingRun& run, double deg) {
  const sim::SceneHit h = run.robot().scene().cast(sim::Vec2(run.robot().xCm(), run.robot().yCm()), deg, 500.0);
  return h.hit ? h.distanceCm : 1e9;
}

TEST(BodyRoomRun, SquareToTheWallsTheCellsEdgesLieOnTheNearestWalls) {
  // Rooms turned so that the walls lie at any offset from where the robot stands.
  for (const double turn : {0.0, 7.0, -23.0}) {
    const sim::Site site = room(turn, -1.03, -0.41);  // the west and south walls within a metre
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      MappingRun run(site, brickConfig(site, "typical", seed, 10.0));
      for (int i = 0; i < 2000 && !run.pilot().explorerStarted(); ++i) run.step();
      ASSERT_TRUE(run.pilot().explorerStarted());
      ASSERT_TRUE(run.pilot().squaring().result().found) << turn << " seed " << seed;
      const Dir h = run.explorer().pose().heading;
      const double heading = run.robot().headingDeg();
      for (int axis = 0; axis < 2; ++axis) {
        // The nearer wall across (axis 0: ahead or behind) and its face's distance from the believed centre.
        const double a = wallAt(run, heading + 90.0 * axis), b = wallAt(run, heading + 90.0 * axis + 180.0);
        if (std::min(a, b) > 90.0) continue;  // beyond PilotConfig::snapRangeCm (and the 6 cm mount): not used
        const Dir towards = rotate(h, a <= b ? axis : axis + 2);
        const double fromCentre = std::min(a, b) + run.pilot().tracker().along(towards) / 10.0;
        // Faces anywhere (RangeGeometry::faceMarginCm): the snap lays them twice the margin past the edge.
        const double inset = run.explorerConfig().geometry.faceMm(1) / 10.0 - 10.0;
        const double offEdge = std::remainder(fromCentre - 10.0 - inset, 20.0);
        EXPECT_LE(std::fabs(offEdge), 2.0) << turn << " seed " << seed << " axis " << axis;
      }
    }
  }
}

}  // namespace
}  // namespace nxtmap::mapping
