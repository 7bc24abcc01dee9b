#include "host/cli/SimRunReport.hpp"

#include <cmath>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/SiteFiles.hpp"
#include "host/cli/WheelFile.hpp"
#include "host/mapping/MapScore.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

const char* endName(ExplorerEnd e) {
  switch (e) {
    case ExplorerEnd::Running: return "running";
    case ExplorerEnd::Complete: return "complete";
    case ExplorerEnd::GridFull: return "grid full";
    case ExplorerEnd::ActionLimit: return "action limit reached";
  }
  return "?";
}

// What the start's sweep found (RunConfig::squareAtStart).
std::string squareLine(const mapping::MappingRun& run) {
  const WallDirectionEstimate& e = run.pilot().squaring().result();
  std::ostringstream out;
  out << "square           ";
  if (!e.found && run.pilot().calibration().turnedBack()) {
    out << "as the calibration's first sweep squared it (its second sweep, " << int{e.dips}
        << " dips, found no wall; the whole turns turned back)";
  } else if (!e.found) {
    out << "no straight wall in range (" << int{e.dips} << " dips): mapped as set down"
        << (run.squaredLate() ? " until the walls it mapped squared it" : "");
  } else {
    out << "walls " << report::formatNumber(e.mrad * 0.18 / 3.141592653589793, 1) << " deg off the start heading ("
        << int{e.agreeing} << " of " << int{e.dips} << " dips agree), turned square: left ";
    const double turned = run.squaredTurnedDeg().value_or(0.0);  // + clockwise
    out << report::formatNumber(std::fabs(turned), 1) << " deg " << (turned < 0 ? "anticlockwise" : "clockwise")
        << " of them";
  }
  return out.str();
}

// What the start's turn calibration measured (RunConfig::calibrateTurns, or one unasked: calibrateUnknownTurns).
std::string calibrationLine(const mapping::MappingRun& run) {
  const TurnCalibration& c = run.pilot().calibration();
  return "calibrated       " + turnCalibrationText(c.found(), c.found() ? c.errorPpm() : 0, c.turns(),
                                                   run.config().calibrateTurns == 0, c.turnedBack());
}

// What the pilot has learnt of the wheels (PoseTracker's drift and turn error), beside the simulated truth.
std::string wheelsLine(const mapping::MappingRun& run) {
  return "wheels learnt    " + wheelsLearntText(run.pilot().wheels(), run.robot().wheels());
}

}  // namespace

std::string simRunReport(const mapping::MappingRun& run, const sim::RobotDescription& robot,
                         const mapping::PoseErrorShare& pose, const std::string& heading,
                         const std::string& wheelsFile) {
  const mapping::RunConfig& cfg = run.config();
  const Counters c = run.counters();
  const mapping::MapScore s = mapping::scoreRun(run);
  auto num = [](double v) { return report::formatNumber(v, 1); };
  std::ostringstream out;
  out << "\nrun              " << run.world().name() << " " << run.world().width() << "x" << run.world().height()
      << " cells of " << robot.cellCm << " cm, robot " << robot.name << ", start " << run.config().startCol << ","
      << run.config().startRow << " heading " << heading;
  if (cfg.startJitterDeg > 0.0) {
    out << " (set down " << report::formatNumber(run.setDownFrameDeg(), 1) << " deg off square)";
  }
  if (run.startMovedCm() > 0.0) {
    out << " (carried " << num(run.startMovedCm())
        << " cm from where it was asked to be set down, to have room to turn)";
  } else if (run.startMovedCm() < 0.0) {
    out << " (no room to turn anywhere near where it was set down)";
  }
  out << ", strategy " << mapping::strategyName(cfg.strategy) << ", noise " << cfg.noise.name << ", seed " << cfg.seed
      << ", range " << report::formatNumber(robot.rangeM) << " m";
  if (!cfg.grid.isBrick()) out << ", grid " << cfg.grid.describe();
  out << "\n";
  if (run.config().squareAtStart) out << squareLine(run) << "\n";
  if (run.pilot().calibration().turns() > 0) out << calibrationLine(run) << "\n";
  if (cfg.storedWheels) out << "wheels stored    read from " << wheelsFile << "\n";
  out << wheelsLine(run) << "\n";
  out << "end              " << endName(run.explorer().end())
      << (run.metGridEdge() && run.explorer().end() == ExplorerEnd::Complete ? " (up to the grid's edge)" : "") << "\n"
      << "time units       " << report::formatNumber(c.timeHalfUnits() / 2.0, 1) << "\n"
      << "sensor requests  " << c.sensorRequests << "\n"
      << "raw samples      " << c.rawSamples << "\n"
      << "cells moved      " << c.cellsMoved << "\n"
      << "turns            " << report::formatNumber(c.turnEighths / 2.0, 1) << " x 90 deg\n"
      << "blocked moves    " << c.blockedMoves << "\n"
      << "detected         " << num(s.detectedPct()) << " % of the observable occupied cells (" << s.detectedOccupied
      << " of " << s.observableOccupied << ")\n"
      << "found/actual occ " << num(s.seedPerformancePct()) << " % (" << s.foundOccupied << " of " << s.actualOccupied
      << ", the thesis's performance)\n"
      << "wrong cells      " << s.wrongCells << "\n"
      << "unknown cells    " << s.unknown << " (" << s.unknownObservable << " of them observable)\n"
      << "free cells       " << s.foundFree << " found of " << s.actualFree << "\n"
      << "unsafe free      " << s.unsafeFree << " cells holding an obstacle that the map calls free\n"
      << "phantom occupied " << s.phantomOccupied << " cells the map calls occupied where there is nothing\n"
      << "lost             " << (s.lost ? "yes: the robot believes it stands in another cell" : "no") << "\n"
      << "aligned          map turned " << num(s.alignRotationDeg) << " deg, moved " << num(s.alignShiftCol) << ","
      << num(s.alignShiftRow) << " cells to fit the world best: detected " << num(s.detectedPctAligned())
      << " %, wrong " << s.wrongCellsAligned << ", unsafe free " << s.unsafeFreeAligned << ", lost "
      << (s.lostAligned ? "yes" : "no") << "\n"
      << "off its belief   heading over " << num(mapping::PoseErrorShare::kHeadingMrad) << " mrad for "
      << num(pose.headingOffPct()) << " % of the actions, centre over a quarter cell for " << num(pose.positionOffPct())
      << " %\n";
  if (run.metGridEdge()) out << gridFullNote(cfg.grid, robot.cellCm, run.world().width(), run.world().height()) << "\n";
  return out.str();
}

std::string traceLine(const mapping::RunTrace& t, const std::string& file) {
  std::ostringstream out;
  out << "wrote " << file << ": ";
  if (t.firstLostStep() == 0)
    out << "the believed cell was the robot's after every action";
  else
    out << "the believed cell first left the robot's after action " << t.firstLostStep() << " (" << t.lostSteps()
        << " actions lost in all)";
  out << "; worst error " << report::formatNumber(t.worstErrorMm(), 0) << " mm, "
      << report::formatNumber(t.worstErrorMrad() * 0.18 / 3.141592653589793, 1) << " deg; outside the tracker's "
      << "3 sigma after " << t.outsideSteps() << " of " << t.mappingSteps() << " actions while mapping";
  return out.str();
}

}  // namespace nxtmap::cli
