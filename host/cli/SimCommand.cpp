#include "host/cli/SimCommand.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/WheelFile.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/mapping/MapScore.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/mapping/PoseErrorShare.hpp"
#include "host/mapping/RunTrace.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/report/MapImage.hpp"
#include "host/report/MapText.hpp"

namespace nxtmap::cli {
namespace {
enum class Show { Live, Final, None };

Show parseShow(const std::string& text) {
  if (text == "live") return Show::Live;
  if (text == "final") return Show::Final;
  if (text == "none") return Show::None;
  throw CliError("--show must be one of live, final, none, not '" + text + "'");
}

const char* endName(ExplorerEnd e) {
  switch (e) {
    case ExplorerEnd::Running: return "running";
    case ExplorerEnd::Complete: return "complete";
    case ExplorerEnd::GridFull: return "grid full";
    case ExplorerEnd::ActionLimit: return "action limit reached";
  }
  return "?";
}

std::string statusLine(const mapping::MappingRun& run) {
  std::ostringstream o;
  const Counters c = run.counters();
  o << mapping::strategyName(run.config().strategy);
  if (const PropagationExplorer* p = run.propagation()) {
    o << " | ";
    if (run.finished())
      o << "done";
    else if (p->sweeping())
      o << "sweep";
    else
      o << propagationName(p->current());
    o << ", " << p->recordCount() << " propagations";
    if (p->recordCount() > 0) {
      o << " (last: " << outcomeName(p->record(static_cast<uint16_t>(p->recordCount() - 1)).outcome) << ")";
    }
  } else if (run.finished()) {
    o << " | done";
  }
  o << " | time " << report::formatNumber(c.timeHalfUnits() / 2.0, 1) << " | sensor reads " << c.sensorRequests
    << " | cells " << c.cellsMoved;
  return o.str();
}

// The run's belief over the whole world, in the world's frame (same size, resolution, origin 0).
mapio::OccupancyMap exploredMap(const mapping::MappingRun& run) {
  const sim::World& w = run.world();
  mapio::OccupancyMap map(w.width(), w.height(), mapio::Occupancy::Unknown, w.resolutionM());
  for (int r = 0; r < w.height(); ++r) {
    for (int c = 0; c < w.width(); ++c) {
      const CellState s = run.belief(c, r);
      if (s == CellState::Free) map.set(c, r, mapio::Occupancy::Free);
      if (s == CellState::Occupied) map.set(c, r, mapio::Occupancy::Occupied);
    }
  }
  return map;
}

void drawFrame(const mapping::MappingRun& run, const report::MapTextOptions& textOptions, bool first) {
  std::string frame = first ? "\x1b[2J\x1b[H" : "\x1b[H";
  frame += report::renderMapText(run, textOptions);
  frame += statusLine(run);
  frame += "\x1b[K\n\x1b[J";
  std::cout << frame << std::flush;
}
}  // namespace

CLI::App* addSimCommand(CLI::App& app, SimOptions& o) {
  CLI::App* sim = app.add_subcommand("sim", "one mapping run in the simulator");
  sim->add_option("world", o.world,
                  "world: Moving AI .map, ROS map_server .yaml, nxtmap world .yaml (worlds/rooms) or HouseExpo .json");
  sim->add_option("--start", o.start,
                  "start cell COL,ROW of a raster world (col right, row down from the top-left); for a world "
                  "file X,Y[,YAW] in its metres (default: the file's own start)");
  sim->add_option("--heading", o.heading, "initial heading N, E, S or W on a raster world (default N)");
  addRangeOption(*sim, o.run);
  addWorldRunOptions(*sim, o.run);
  addGridOption(*sim, o.run);
  addSquareOption(*sim, o.run);
  sim->add_option("--seed", o.seed, "random seed of the noise (default 1)");
  sim->add_option("--strategy", o.strategy, "exploration strategy: propagation, frontier (default propagation)");
  sim->add_option("--show", o.show, "display: live, final, none (default final)");
  sim->add_option("--delay-ms", o.delayMs, "live mode: delay per frame in ms (default 30)");
  sim->add_option("--save", o.save, "save the explored map as ROS map_server FILE.yaml + FILE.pgm (world frame)");
  sim->add_option("--png", o.png, "write a PNG of the final map (missed obstacles light red, wrong cells orange)");
  sim->add_option("--trace", o.trace,
                  "write a CSV of the pose the robot believes and the pose it truly has after every action "
                  "(explorer frame, mm and mrad), to see where a lost run went astray");
  sim->add_option("--wheels", o.wheels,
                  "the wheels' errors the robot keeps (YAML), as the brick keeps them from run to run: read at the "
                  "start when the file exists (else nothing is stored), what the run learnt written at its end");
  return sim;
}

namespace {

// What the start's sweep found (RunConfig::squareAtStart).
std::string squareLine(const mapping::MappingRun& run) {
  const WallDirectionEstimate& e = run.pilot().squaring().result();
  std::ostringstream out;
  out << "square           ";
  if (!e.found) {
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
  return "calibrated       " +
         turnCalibrationText(c.found(), c.found() ? c.errorPpm() : 0, c.turns(), run.config().calibrateTurns == 0);
}

// What the pilot has learnt of the wheels (PoseTracker's drift and turn error), beside the simulated truth.
std::string wheelsLine(const mapping::MappingRun& run) {
  return "wheels learnt    " + wheelsLearntText(run.pilot().wheels(), run.robot().wheels());
}

// Where the trace went and what it shows of the belief leaving the robot's cell.
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

}  // namespace

int runSim(const SimOptions& o) {
  if (printNoiseListIfAsked(o.run)) return kExitOk;
  requirePositional(o.world, "sim: world");
  mapping::RunConfig config;
  const sim::RobotDescription robot = robotOf(o.run);
  config.robot = robot;
  config.startJitterDeg = checkStartJitter(o.run.startJitterDeg);
  config.squareAtStart = squareAtStart(o.run.square, robot);
  const CalibrationChoice calibration = calibrationOf(o.run);
  config.calibrateTurns = calibration.turns;
  config.calibrateUnknownTurns = calibration.whenUnknown;
  config.noise = parseNoise(o.run.noise);
  config.seed = parseSeed(o.seed);
  parseHeading(o.heading);
  config.strategy = parseStrategy(o.strategy);
  config.grid = gridOf(o.run);
  const Show show = parseShow(o.show);
  if (o.delayMs < 0 || o.delayMs > 10000) {
    throw CliError("--delay-ms must lie in 0..10000, not " + std::to_string(o.delayMs));
  }
  if (!o.save.empty()) {
    const std::string ext = std::filesystem::path(o.save).extension().string();
    if (ext != ".yaml" && ext != ".yml") throw CliError("--save must name a .yaml file, not '" + o.save + "'");
  }
  std::string outputError;  // the outputs are checked before the run (a missing folder, a device): nothing written yet
  if (!o.trace.empty() && std::filesystem::path(o.trace).extension() != ".csv") {
    throw CliError("--trace must name a .csv file, not '" + o.trace + "'");
  }
  for (const std::string& out : {o.png, o.save, o.trace, o.wheels}) {
    if (!out.empty() && !fileio::resolveOutputTarget(out, outputError)) throw CliError(outputError);
  }
  if (!o.wheels.empty()) {
    std::string error;
    config.storedWheels = readWheelFile(o.wheels, error);
    if (!error.empty()) throw CliError(error);
  }
  const sim::Site site = loadSiteFile(o.world, robot.cellCm);
  config.startPose = parseSiteStart(site, o.start, o.heading);
  checkStartFits(site, robot, *config.startPose);

  report::MapTextOptions textOptions;
  textOptions.color = colorWanted();
  mapping::MappingRun run(site, config);
  const sim::World& world = run.world();
  std::ostringstream traceText;
  std::optional<mapping::RunTrace> trace;
  if (!o.trace.empty()) trace.emplace(traceText);
  mapping::PoseErrorShare pose;
  if (show == Show::Live) drawFrame(run, textOptions, true);
  for (uint64_t n = 1; !run.finished(); ++n) {
    const DriveAction done = run.lastAction();
    run.step();
    if (trace) trace->record(run, n, done);
    pose.add(run);
    if (show != Show::Live) continue;
    // Redraw when the robot moved or turned (reads and steering alone would make the display crawl).
    const bool turned = done.kind == DriveAction::Kind::Rotate && (done.value > 700 || done.value < -700);
    if (done.kind == DriveAction::Kind::Drive || turned || run.finished()) {
      drawFrame(run, textOptions, false);
      if (o.delayMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(o.delayMs));
    }
  }
  if (show == Show::Final) std::cout << report::renderMapText(run, textOptions) << statusLine(run) << '\n';

  const Counters c = run.counters();
  const mapping::MapScore s = mapping::scoreRun(run);
  auto num = [](double v) { return report::formatNumber(v, 1); };
  std::ostringstream out;
  out << "\nrun              " << world.name() << " " << world.width() << "x" << world.height() << " cells of "
      << robot.cellCm << " cm, robot " << robot.name << ", start " << run.config().startCol << ","
      << run.config().startRow << " heading " << o.heading;
  if (config.startJitterDeg > 0.0) {
    out << " (set down " << report::formatNumber(run.setDownFrameDeg(), 1) << " deg off square)";
  }
  if (run.startMovedCm() > 0.0) {
    out << " (carried " << num(run.startMovedCm())
        << " cm from where it was asked to be set down, to have room to turn)";
  } else if (run.startMovedCm() < 0.0) {
    out << " (no room to turn anywhere near where it was set down)";
  }
  out << ", strategy " << mapping::strategyName(config.strategy) << ", noise " << config.noise.name << ", seed "
      << config.seed << ", range " << report::formatNumber(robot.rangeM) << " m";
  if (!config.grid.isBrick()) out << ", grid " << config.grid.describe();
  out << "\n";
  if (run.config().squareAtStart) out << squareLine(run) << "\n";
  if (run.pilot().calibration().turns() > 0) out << calibrationLine(run) << "\n";
  if (config.storedWheels) out << "wheels stored    read from " << o.wheels << "\n";
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
  if (run.metGridEdge()) out << gridFullNote(config.grid, robot.cellCm, world.width(), world.height()) << "\n";
  std::cout << out.str() << std::flush;

  if (!o.png.empty()) {
    std::string error;
    if (!report::writeMapPng(o.png, run, report::MapImageOptions{}, error)) throw CliError(error);
    std::cout << "wrote " << o.png << "\n";
  }
  if (trace) {
    std::string error;
    if (!fileio::writeFileAtomically(o.trace, traceText.str(), error)) throw CliError(error);
    std::cout << traceLine(*trace, o.trace) << "\n";
  }
  if (!o.save.empty()) {
    std::string error;
    if (!mapio::saveRosMap(exploredMap(run), o.save, error)) throw CliError(error);
    std::cout << "wrote " << o.save << " and " << mapio::pgmNameFor(o.save) << "\n";
  }
  if (!o.wheels.empty()) {
    std::string error;
    if (!fileio::writeFileAtomically(o.wheels, wheelFileText(run.pilot().wheels()), error)) throw CliError(error);
    std::cout << "wrote " << o.wheels << ": the wheels learnt, for the next run\n";
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
