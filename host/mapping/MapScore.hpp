#pragma once
#include <vector>

#include "common/grid/CellState.hpp"
#include "host/mapping/MapAlignment.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/sim/GridFrame.hpp"
#include "host/sim/Scene.hpp"
#include "host/sim/World.hpp"
#include "host/sim/WorldTruth.hpp"

namespace nxtmap::mapping {

// How a finished run's map compares with the world (the published Appendix A columns plus
// the checks the method's safety argument needs). Truth: the scene on the robot's grid by the safe rule
// (sim::rasterizeScene); "the start frame" is the robot's grid as set down, "aligned" the same map moved
// by the best rigid alignment to the scene (MapAlignment).
struct MapScore {
  int actualFree = 0;          // free cells of the world map
  int foundFree = 0;           // cells the map holds as free
  int actualOccupied = 0;      // blocked cells of the world map (walls included)
  int foundOccupied = 0;       // cells the map holds as occupied
  int unknown = 0;             // world cells the map still holds as unknown
  int wrongCells = 0;          // map cells that disagree with the world (incl. outside the world)
  int observableOccupied = 0;  // blocked cells some reachable cell can see
  int detectedOccupied = 0;    // ... of which the map holds as occupied
  int observableFree = 0;
  int unknownObservable = 0;  // cells some reachable cell can see, still unknown
  // Safety, start frame: wrongCells = unsafeFree + phantomOccupied.
  int unsafeFree = 0;       // cells holding an obstacle (or outside the world) that the map calls free
  int phantomOccupied = 0;  // cells the map calls occupied where the truth is free
  bool lost = false;        // the believed cell at the end is not the cell holding the robot's centre

  // The same after the best rigid alignment of the map to the scene: rotation about the start point
  // (degrees, + clockwise) then a shift in the plane (cells of the start frame's col/row axes).
  double alignRotationDeg = 0.0;
  double alignShiftCol = 0.0, alignShiftRow = 0.0;
  int observableOccupiedAligned = 0;
  int detectedOccupiedAligned = 0;
  int wrongCellsAligned = 0;
  int unsafeFreeAligned = 0;
  int phantomOccupiedAligned = 0;
  bool lostAligned = false;

  double detectedPct() const { return observableOccupied == 0 ? 100.0 : 100.0 * detectedOccupied / observableOccupied; }
  double detectedPctAligned() const {
    return observableOccupiedAligned == 0 ? 100.0 : 100.0 * detectedOccupiedAligned / observableOccupiedAligned;
  }
  // The thesis's "performance": found occupied / actual occupied.
  double seedPerformancePct() const { return actualOccupied == 0 ? 100.0 : 100.0 * foundOccupied / actualOccupied; }
};

// Everything a score needs, apart from any MappingRun (tests build it by hand).
struct ScoreInput {
  const sim::Scene* scene = nullptr;     // the geometry; null: no alignment (aligned = start frame)
  const sim::World* truth = nullptr;     // the scene rasterised on `frame` (required)
  sim::GridFrame frame;                  // the robot's grid
  int startCol = 0, startRow = 0;        // start cell on `frame`; its centre is the rotation centre
  int freeCells = 1, hitCells = 1;       // RangeGeometry: cells a reading can prove free / occupied
  std::vector<KnownCell> known;          // the map's known cells (each cell at most once)
  int believedCol = 0, believedRow = 0;  // the robot's own idea of its cell at the end
  sim::Vec2 trueCentreCm{0.0, 0.0};      // its true centre at the end, plane cm
};

MapScore scoreMap(const ScoreInput& in);
MapScore scoreRun(const MappingRun& run);

}  // namespace nxtmap::mapping
