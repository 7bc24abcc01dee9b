#include "host/cli/SimCommand.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/SimRunReport.hpp"
#include "host/cli/WheelFile.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/mapio/MapFiles.hpp"
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
  sim->add_option(
      "--png", o.png,
      "write a PNG of the final map (missed obstacles light red, obstacles mapped free orange, walls mapped on "
      "open floor blue)");
  sim->add_option("--trace", o.trace,
                  "write a CSV of the pose the robot believes and the pose it truly has after every action "
                  "(explorer frame, mm and mrad), to see where a lost run went astray");
  sim->add_option("--wheels", o.wheels,
                  "the wheels' errors the robot keeps (YAML), as the brick keeps them from run to run: read at the "
                  "start when the file exists (else nothing is stored), what the run learnt written at its end");
  return sim;
}

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

  std::cout << simRunReport(run, robot, pose, o.heading, o.wheels) << std::flush;

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
