#pragma once
#include "host/mapping/MappingRun.hpp"
#include "host/sim/WorldTruth.hpp"

namespace nxtmap::mapping {

// How a finished run's map compares with the world (the published Appendix A columns plus
// the checks the method's safety argument needs).
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
  int unknownObservable = 0;   // cells some reachable cell can see, still unknown
  double detectedPct() const {
    return observableOccupied == 0 ? 100.0 : 100.0 * detectedOccupied / observableOccupied;
  }
  // The thesis's "performance": found occupied / actual occupied.
  double seedPerformancePct() const {
    return actualOccupied == 0 ? 100.0 : 100.0 * foundOccupied / actualOccupied;
  }
};

MapScore scoreRun(const MappingRun& run);

}  // namespace nxtmap::mapping
