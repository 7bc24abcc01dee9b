#pragma once
#include <cstdint>

#include "common/explore/ExplorerConfig.hpp"
#include "firmware/drivers/MotionGeometry.hpp"

namespace nxtmap::fw {

// The robot as built: which port holds what, its dimensions and the sensor range it trusts.
// One place to change. The NXTMAP_SIM_GEOMETRY build (nxtmap-sim.elf) uses the simulator's
// published-experiment geometry instead (10 cm cells, 5 cm - 1 m, sensors at the centre), so an
// emulated run can be compared cell by cell with the host's MappingRun.
struct BrickConfig {
  // Sensor port (0 = port 1) of each Sensor (Front, Right, Back, Left).
  uint8_t sensorPorts[4] = {0, 1, 2, 3};
  // Output (0 = A) of each wheel; positive power drives forward.
  uint8_t leftMotor = 0;
  uint8_t rightMotor = 1;
  // The PC's Calibrate: whole turns between the two sweeps (TurnCalibration: 4 give the turns' error to about
  // 0.1 % in a plain room).
  uint8_t calibrationTurns = 4;
#if defined(NXTMAP_SIM_GEOMETRY)
  MotionGeometry drive{56, 112, 100, 360};  // 10 cm cells
  int16_t minCm = 5, maxCm = 100, mountCm = 0;
  int16_t blindCm = 0;                                // a near obstacle reads too near (the published model)
  int8_t faceMarginCm = 0;                            // the published raster worlds: faces on cell edges
  int8_t echoMarginCm = 0;
  int16_t sureCm = 0;                                 // every echo marks the cell on the axis (published)
  int16_t sonarScalePer10k = 10000, sonarBiasMm = 0;  // readings as they come, as the published robot
  bool turnNeedsRoom = false;                         // a point
  int16_t squareSweepMrad = 0;                        // set down square on a cell's centre, as the published runs
#else
  MotionGeometry drive{};  // 56 mm wheels, 112 mm track, 200 mm cells
  int16_t minCm = 7;       // the LEGO sensor is unreliable closer than this
  int16_t maxCm = 120;     // and beyond this
  int16_t mountCm = 6;     // sensor faces ahead of the robot's centre
  // Nearer than this the LEGO sensor returns no echo at all (about 7 cm, docs/nxt-sonar-and-odometry.md): "no
  // echo" does not vouch for a cell reaching into it (RangeGeometry::blindCm).
  int16_t blindCm = 7;
  // An echo farther than this may come from beside the sensor's axis and marks no cell occupied (it proves the
  // cells before it free: RangeGeometry::sureCm): where a beam of 10 degrees half-angle (the narrow end of the
  // 10-20 judged for the LEGO sensor, docs/nxt-sonar-and-odometry.md) spreads past half a cell each side:
  // 10 cm / tan 10 deg - 6 cm. The simulator derives it from its sonar's cone: 50 cm under `nxt` too.
  int16_t sureCm = 50;
  // Walls stand anywhere, not on the cells' edges: the pilot learns where faces lie (RangeGeometry), and the
  // start's snap lays the nearest faces 8 cm into their cells (twice faceMarginCm), where a face not yet learnt is
  // taken to lie. Brick rooms under `nxt`, 60 seeds, against 3 cm (the echoes' margin then the same): propagation
  // 93.1 -> 95.0 % detected, unsafe free 2.5 -> 1.7 % of the occupied cells, lost 39 -> 28 of 1,080 runs.
  int8_t faceMarginCm = 4;
  // An echo marks the cell holding its face brought 1 cm nearer (the whole-cm reading): a face less than that past
  // an edge marks the cell before it. Against 4 cm (faceMarginCm's, as until 2026-12-08), brick rooms, `nxt`,
  // jitter 10, seeds 1-60, paired: propagation +0.96 +- 0.23 points detected, frontier +1.24 +- 0.36 (seeds 1-30
  // and 31-60 alike), walls on open floor 2.3 -> 0.9 a run, obstacles held free 1.16 -> 1.34 % of the occupied
  // cells, lost 19 -> 21 and 52 -> 62 of 1,080; houses (frontier, seeds 1-60) 91.4 -> 92.8 %, every plan room
  // mapped in 217 -> 254 of 300 runs. 0, 2 and 3 cm measured worse.
  int8_t echoMarginCm = 1;
  // The LEGO 9846 sensor's linear error, taken off every reading (RangeGeometry::scalePer10k, biasMm): raw =
  // 0.9757 x true + 1.88 cm (docs/nxt-sonar-and-odometry.md). A sensor measured otherwise: its own fit here.
  int16_t sonarScalePer10k = 9757;
  int16_t sonarBiasMm = 19;
  // The 16 x 18 cm body sweeps 12 cm from its centre when it turns, more than half a cell: it turns only
  // where the four cells around it are known free (ExplorerConfig::turnNeedsRoom).
  bool turnNeedsRoom = true;
  // Set down anyhow: a run on an empty map first sweeps +-90 degrees and turns square to the walls
  // (PilotConfig::squareSweepMrad).
  int16_t squareSweepMrad = 1571;
#endif

  ExplorerConfig explorer() const {
    ExplorerConfig c;
    c.geometry.cellCm = static_cast<int16_t>(drive.cellMm / 10);
    c.geometry.minCm = minCm;
    c.geometry.maxCm = maxCm;
    c.geometry.mountCm = mountCm;
    c.geometry.blindCm = blindCm;
    c.geometry.sureCm = sureCm;
    c.geometry.faceMarginCm = faceMarginCm;
    c.geometry.echoMarginCm = echoMarginCm;
    c.geometry.scalePer10k = sonarScalePer10k;
    c.geometry.biasMm = sonarBiasMm;
    c.turnNeedsRoom = turnNeedsRoom;
    return c;
  }
};

}  // namespace nxtmap::fw
