#include "host/cli/EmulatedMapScore.hpp"

#include <cmath>
#include <sstream>

#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/SimDrive.hpp"
#include "host/mapping/SquaredGrid.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/report/MapImage.hpp"
#include "host/sim/SceneAxes.hpp"
#include "host/sim/StartJitter.hpp"
#include "host/sim/TruthRaster.hpp"

namespace nxtmap::cli {

EmulatedMap layEmulatedMap(const emu::Brick& brick, const RadioMirror& radio, const sim::SonarNoise& sonar) {
  const sim::RobotPlacement& placed = brick.placement();
  const ExplorerStart& start = radio.explorerStart();
  const sim::Scene& scene = *placed.scene;
  const double axis = start.headingDeg - std::remainder(start.headingDeg - sim::sceneAxesDeg(scene), 90.0);
  const auto heading = static_cast<sim::Heading>(sim::squareQuarter(axis));
  const sim::Vec2 centre = mapping::believedCellCentre(start.centreCm, axis, start.offsetYCm, start.offsetXCm);
  const sim::Placement grid = sim::placeOnGrid(scene, centre, sim::squareRemainderDeg(axis), placed.robot.cellCm);
  EmulatedMap m{sim::rasterizeScene(scene, grid.frame, grid.width, grid.height, placed.truth.name()), {}, heading};
  const ExplorerConfig explorer = mapping::explorerConfigFor(m.truth, placed.robot, sonar, placed.robot.minRangeM,
                                                             placed.robot.rangeM, -1.0, -1, 1);

  mapping::ScoreInput& in = m.input;
  in.scene = &scene;
  in.frame = grid.frame;
  in.startCol = grid.startCol;
  in.startRow = grid.startRow;
  in.freeCells = explorer.geometry.freeCells();
  in.hitCells = explorer.geometry.hitCells();
  const mapping::FrameTransform frame(in.startCol, in.startRow, heading);
  radio.map().forEach([&](Cell c, CellState state) {
    if (state == CellState::Unknown) return;
    mapping::KnownCell k;
    k.state = state;
    frame.toWorld(c, k.col, k.row);
    in.known.push_back(k);
  });
  in.trueCentreCm = sim::Vec2(brick.robot().xCm(), brick.robot().yCm());
  in.believedCol = in.believedRow = -1;  // no Status: no cell of the grid, lost
  if (const std::optional<protocol::StatusMsg>& status = radio.status()) {
    frame.toWorld(status->pose.cell, in.believedCol, in.believedRow);
    m.heading = frame.toWorld(status->pose.heading);
  }
  return m;
}

mapping::MapScore scoreEmulatedMap(const EmulatedMap& map) {
  mapping::ScoreInput in = map.input;
  in.truth = &map.truth;
  return mapping::scoreMap(in);
}

bool writeEmulatedMapPng(const std::string& path, const EmulatedMap& map, std::string& error) {
  const sim::World& world = map.truth;
  const auto index = [&](int col, int row) {
    return static_cast<size_t>(row) * static_cast<size_t>(world.width()) + static_cast<size_t>(col);
  };
  std::vector<CellState> cells(index(0, world.height()), CellState::Unknown);
  for (const mapping::KnownCell& k : map.input.known)
    if (world.inside(k.col, k.row)) cells[index(k.col, k.row)] = k.state;
  report::BeliefPicture p;
  p.world = &world;
  p.belief = [&](int col, int row) { return cells[index(col, row)]; };
  p.robotCol = map.input.believedCol;
  p.robotRow = map.input.believedRow;
  p.heading = map.heading;
  return report::writePng(path, report::renderBeliefImage(p), error);
}

std::string scoreLines(const mapping::MapScore& m) {
  const auto num = [](double v) { return report::formatNumber(v, 1); };
  std::ostringstream out;
  out << "detected         " << num(m.detectedPct()) << " % of the observable occupied cells (" << m.detectedOccupied
      << " of " << m.observableOccupied << "), in the map that came over the radio\n"
      << "wrong cells      " << m.wrongCells << " (unsafe free " << m.unsafeFree << ", phantom occupied "
      << m.phantomOccupied << ")\n"
      << "aligned          map turned " << num(m.alignRotationDeg) << " deg, moved " << num(m.alignShiftCol) << ","
      << num(m.alignShiftRow) << " cells to fit the world best: detected " << num(m.detectedPctAligned())
      << " %, wrong " << m.wrongCellsAligned << "\n"
      << "lost             " << (m.lost ? "yes: the brick believes it stands in another cell" : "no") << "\n";
  return out.str();
}

}  // namespace nxtmap::cli
