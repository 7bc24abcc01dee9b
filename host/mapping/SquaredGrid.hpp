// The grid a robot maps on once its start's sweep is over: turned square to the scene's walls (or, with no
// straight wall seen, as it was set down) and with the cell's centre where the pilot's snap put it. The
// simulator lays the truth on it, so that a run is scored on the grid it mapped (MappingRun, HouseMapper).
#pragma once

#include "common/explore/Pose.hpp"
#include "common/motion/Pilot.hpp"
#include "host/sim/Heading.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/TruthRaster.hpp"

namespace nxtmap::mapping {

struct SquaredGrid {
  bool moved = false;       // false: the grid as laid when the robot was set down (nothing to re-lay)
  bool found = false;       // the sweep saw the walls
  double offDeg = 0.0;      // found: degrees from the robot's heading to the walls' nearest axis (0..45)
  double turnedDeg = 0.0;   // found: the same with its sign, + the robot clockwise of that axis (-45..45)
  sim::Placement placement;  // moved: the grid over the scene, the start cell the robot's believed cell
  sim::Heading heading = sim::Heading::N;  // moved: the explorer's heading in that grid's terms
};

// `setDownHeading`: the heading the run's grid was laid with; `setDownCm`: where the robot's centre was set
// down; `explorerHeading`: the explorer's now. A robot that drove off (towards a far wall, to find one:
// PilotConfig::approaches) maps from where it stands, walls found or not: its grid moves with it.
SquaredGrid squaredGrid(const sim::SimRobot& robot, const Pilot& pilot, Dir explorerHeading,
                        sim::Heading setDownHeading, const sim::Vec2& setDownCm);

// The grid on which the robot's belief is right as it stands: turned to the axis it believes it faces (its true
// heading less the tracker's theta) and laid with `explorer`'s cell where it believes it stands; `origin` is then
// the world cell of the explorer's origin on it. For a robot whose sweeps saw no straight wall: mapping, it turns
// square to the walls it reads (the tracker's heading, learnt from them), and its grid is laid where its belief
// holds once that heading is known (MappingRun).
struct BelievedGrid {
  sim::Placement placement;                // the grid over the scene
  sim::Heading heading = sim::Heading::N;  // the world heading of the explorer's north on it
  int originCol = 0, originRow = 0;        // the explorer's cell 0,0 on it
};
BelievedGrid believedGrid(const sim::SimRobot& robot, const Pilot& pilot, const Pose& explorer);

// The centre of the cell a robot at `robotCm` (plane cm) believes it stands `forwardCm` ahead of and `rightCm` to
// the right of, on a grid whose explorer heading is the compass heading `axisDeg`.
sim::Vec2 believedCellCentre(const sim::Vec2& robotCm, double axisDeg, double forwardCm, double rightCm);

}  // namespace nxtmap::mapping
