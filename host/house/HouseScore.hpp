// HouseScore: how a mapped house compares with the world and with the floor plan.
#pragma once

#include <vector>

#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/sim/WorldTruth.hpp"

namespace nxtmap::house {

struct HouseScore {
  int observable = 0;      // world cells some reachable cell can observe (the method's sensing)
  int agree = 0;           // ... that the merged map holds in the world's state
  int unknown = 0;         // ... that the merged map holds as unknown
  int wrong = 0;           // ... that the merged map holds in the other state
  int wallsOnFloor = 0;    // ... of them: occupied in the map, open floor in the world (the rest: obstacles held free)
  int wrongElsewhere = 0;  // known map cells outside the observable set that disagree with the world
  int rooms = 0;           // room maps in the network
  int gateways = 0;
  double agreementPct() const { return observable == 0 ? 100.0 : 100.0 * agree / observable; }
};

// A mapped house and the world it was mapped in: the house frame (room 0's) in world cells, the
// start cell, and the robot's sonar geometry (what a reachable cell can observe).
struct HouseInWorld {
  const network::HouseNetwork* network = nullptr;
  const sim::World* world = nullptr;
  mapping::FrameTransform houseFrame{0, 0, sim::Heading::N};
  int startCol = 0, startRow = 0;
  RangeGeometry geometry;
  // The world's grid on the plan's plane, for placing plan rooms by their plane boxes (PlanRoom::containsPoint);
  // nullptr: the plan's room boxes are the world's cells (movePlanOntoGrid). Not owned.
  const sim::GridFrame* grid = nullptr;
};

// The house `mapper` mapped, in its world.
HouseInWorld houseInWorld(const HouseMapper& mapper);

HouseScore scoreHouse(const HouseMapper& mapper);
HouseScore scoreHouse(const HouseInWorld& house);
// What a reachable cell of the house's world can observe (its start, its sonar geometry), and the score
// against it: for scoring one world many times (it does not depend on the map).
sim::Observability observabilityOf(const HouseInWorld& house);
HouseScore scoreHouse(const HouseInWorld& house, const sim::Observability& observable);

// Plan rooms (room boxes) whose reachable free cells the merged map holds as free to at least
// `minPct` percent; rooms with no reachable cell are not counted in `reachable`.
struct PlanCoverage {
  int planRooms = 0;  // boxes in the plan
  int reachable = 0;  // boxes holding reachable free cells
  int covered = 0;    // ... mapped to at least minPct
};
PlanCoverage planCoverage(const HouseMapper& mapper, const HousePlan& plan, double minPct = 90.0);
PlanCoverage planCoverage(const HouseInWorld& house, const HousePlan& plan, double minPct = 90.0);
// The same with the plan's rooms placed on the robot's grid by their plane boxes: any grid, at any cell size and
// turned as the start's squaring left it (the brick's 20 cm cells on a plan rasterised at 10 cm).
PlanCoverage planCoverageOnGrid(const HouseMapper& mapper, const HousePlan& plan, double minPct = 90.0);

// Moves the plan's room boxes from its raster's cells onto the robot's grid `frame` (whose cell (0, 0) is
// centred on frame.originCm): possible when the grid has the raster's cells, is square to it and its cell
// centres are the raster's (the robot set down square on a cell centre). False otherwise (plan unchanged).
bool movePlanOntoGrid(HousePlan& plan, const sim::World& truth, const sim::GridFrame& frame);

// Names the mapped rooms after the plan: each plan room box whose centre (or nearest free cell
// to it) is a free cell of a room map gets a label there, the category in lower case ("kitchen",
// "kitchen_2" for a second one). The user's naming of rooms, in the simulator. onRobotGrid: the
// rooms are placed by their plane boxes on the grid the run ended with (as planCoverageOnGrid), else
// their boxes are the world's cells (movePlanOntoGrid).
void labelRoomsFromPlan(HouseMapper& mapper, const HousePlan& plan, bool onRobotGrid = false);

}  // namespace nxtmap::house
