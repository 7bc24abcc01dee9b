// A robot whose start sweeps saw no straight wall maps knowing its heading only as well as a person sets a robot
// down (10 degrees), squares against the walls it maps (their slopes along its runs) and is scored on the grid
// laid where its belief held once its heading was known; a robot squared at the start is scored as laid then.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/mapping/MapScore.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/mapping/RunTrace.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/worlds/SiteFiles.hpp"

namespace nxtmap::mapping {
namespace {

// The published start-positions room at 20 cm cells (a 4.4 m room with blocks in it), the brick under nxt set
// down within 10 degrees of square at cell 5,14 (propagation).
RunConfig startPositions(uint64_t seed) {
  RunConfig c;
  c.startJitterDeg = 10;
  c.noise = *sim::noiseProfileByName("nxt");
  c.seed = seed;
  c.robot = *sim::robotByName("brick");
  c.squareAtStart = true;
  return c;
}

struct Outcome {
  bool found = false;           // the start's sweeps saw the walls
  double startSdMrad = 0.0;     // the tracker's heading sigma as the explorer starts
  bool late = false;            // the truth was laid again once the heading was known
  double detectedPct = 0.0;     // of the observable occupied cells, at the end
  bool lost = false;            // at the end
  double headingErrMrad = 0.0;  // truth minus belief, at the end
};

Outcome run(uint64_t seed) {
  const worlds::SiteLoad load =
      worlds::loadSite(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/start-positions.map", 20);
  EXPECT_TRUE(load.site && load.site->raster) << load.error;
  RunConfig c = startPositions(seed);
  c.startPose = load.site->rasterStart(5, 14, 0.0);
  MappingRun r(*load.site, c);
  Outcome o;
  for (int i = 0; i < 5000 && !r.pilot().explorerStarted(); ++i) r.step();
  EXPECT_TRUE(r.pilot().explorerStarted());
  o.found = r.pilot().squaring().result().found;
  o.startSdMrad = std::sqrt(static_cast<double>(r.pilot().tracker().thetaVariance()));
  r.runToEnd();
  o.late = r.squaredLate();
  const MapScore s = scoreRun(r);
  o.detectedPct = 100.0 * s.detectedOccupied / s.observableOccupied;
  o.lost = s.lost;
  o.headingErrMrad = tracePose(r).errThetaMrad;
  return o;
}

TEST(LateSquaring, ARobotWhoseSweepsSawNoWallSquaresAgainstTheWallsItMaps) {
  // Seed 5: five sweeps and four approaches find no straight wall (StartSquaringRun).
  const Outcome o = run(5);
  ASSERT_FALSE(o.found);
  EXPECT_GE(o.startSdMrad, 170.0) << "its heading is known only to about 10 degrees";
  EXPECT_TRUE(o.late) << "the walls it mapped told it its heading";
  EXPECT_FALSE(o.lost);
  EXPECT_LE(std::fabs(o.headingErrMrad), 50.0);
  EXPECT_GE(o.detectedPct, 90.0);
}

TEST(LateSquaring, ARobotSquaredAtTheStartIsScoredAsLaidThen) {
  const Outcome o = run(2);
  ASSERT_TRUE(o.found);
  EXPECT_LE(o.startSdMrad, 30.0);
  EXPECT_FALSE(o.late);
}

}  // namespace
}  // namespace nxtmap::mapping
