#include "host/cli/SimHouseCommand.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/WheelFile.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/house/BestFramesScore.hpp"
#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/house/HouseTrace.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/report/MapImage.hpp"

namespace nxtmap::cli {
namespace {
bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The merged map of the house on its world's raster, against the world, with the robot where it truly ended.
report::RgbImage housePicture(const house::HouseMapper& mapper) {
  const house::HouseInWorld h = house::houseInWorld(mapper);
  const network::RoomMap merged = h.network->merged();
  report::BeliefPicture p;
  p.world = h.world;
  p.belief = [&](int col, int row) { return merged.at(h.houseFrame.toExplorer(col, row)); };
  const sim::SimRobot& robot = mapper.robot();
  const sim::Vec2 at = robot.frame().toGrid(sim::Vec2(robot.xCm(), robot.yCm()));
  p.robotCol = static_cast<int>(std::lround(at.x()));
  p.robotRow = static_cast<int>(std::lround(at.y()));
  return report::renderBeliefImage(p);  // 8 px a cell, fewer for a large house (report::pictureCellPx)
}

// Where the trace went and what it shows of the belief leaving the robot's cell.
std::string traceLine(const house::HouseTrace& t, const std::string& file) {
  std::ostringstream out;
  out << "wrote " << file << ": " << t.steps() << " actions; ";
  if (t.firstLostStep() == 0)
    out << "the believed cell was the robot's after every action";
  else
    out << "the believed cell first left the robot's after action " << t.firstLostStep() << " (" << t.lostSteps()
        << " actions lost in all)";
  return out.str();
}
}  // namespace

CLI::App* addSimHouseCommand(CLI::App& app, SimHouseOptions& o) {
  CLI::App* c = app.add_subcommand("sim-house", "map a house room by room in the simulator");
  c->add_option("world", o.world,
                "world: HouseExpo .json plan, Moving AI .map, ROS map_server .yaml or nxtmap world .yaml");
  c->add_option("--start", o.start,
                "start cell COL,ROW of a raster world (col right, row down); for a world file X,Y[,YAW] in its "
                "metres; optional for a .json plan and a world file with a start");
  c->add_option("--heading", o.heading, "initial heading N, E, S or W (default N)");
  addRangeOption(*c, o.run);
  addWorldRunOptions(*c, o.run);
  addSquareOption(*c, o.run);  // the first room only: every later one is entered square through its doorway
  addGridOption(*c, o.run);
  c->add_option("--seed", o.seed, "random seed of the noise (default 1)");
  c->add_option("--strategy", o.strategy,
                "exploration strategy per room: propagation, frontier (default frontier: fewer turns, so the pose "
                "holds better across rooms)");
  c->add_option("--save", o.save, "directory to save the house in (ROS map per room + house.yaml)");
  c->add_option("--trace", o.trace,
                "write every action's believed and true pose, on the world's raster, to this .csv (which room or "
                "travel it belonged to, readings, the pose tracker's offset, whether the belief left the robot's "
                "cell)");
  c->add_option("--png", o.png,
                "write a PNG of the merged map on the world's raster (missed obstacles light red, obstacles mapped "
                "free orange, walls mapped on open floor blue, the robot red where it truly ended)");
  return c;
}

int runSimHouse(const SimHouseOptions& o) {
  if (printNoiseListIfAsked(o.run)) return kExitOk;
  requirePositional(o.world, "sim-house: world");
  house::HouseConfig config;
  parseHeading(o.heading);
  const sim::RobotDescription robot = robotOf(o.run);
  config.robot = robot;
  config.startJitterDeg = checkStartJitter(o.run.startJitterDeg);
  config.squareAtStart = squareAtStart(o.run.square, robot);
  const CalibrationChoice calibration = calibrationOf(o.run);
  config.calibrateTurns = calibration.turns;
  if (calibration.turns > 0) config.squareAtStart = true;  // it measures against the walls of the sweep
  config.calibrateUnknownTurns = calibration.whenUnknown;
  config.noise = parseNoise(o.run.noise);
  config.seed = parseSeed(o.seed);
  config.strategy = parseStrategy(o.strategy);
  config.grid = gridOf(o.run);
  std::optional<house::HousePlan> plan;
  if (endsWith(o.world, ".json")) {  // the plan's rooms label the mapped ones and score the coverage
    house::HousePlanLoad l = house::loadHouseExpo(o.world);
    if (!l.plan) throw CliError(l.error);
    plan = std::move(l.plan);
  }
  const sim::Site site = loadSiteFile(o.world, robot.cellCm);
  config.startPose = parseSiteStart(site, o.start, o.heading);
  checkStartFits(site, robot, *config.startPose);
  std::string saveError;  // --save is checked before the run, so a bad target does not cost the mapping run
  if (!o.save.empty() && !network::checkHouseTarget(o.save, saveError)) throw CliError(saveError);
  if (!o.trace.empty()) {
    if (std::filesystem::path(o.trace).extension() != ".csv")
      throw CliError("--trace must name a .csv file, not '" + o.trace + "'");
    std::string traceError;
    if (!fileio::resolveOutputTarget(o.trace, traceError)) throw CliError(traceError);
  }
  std::string pngError;
  if (!o.png.empty() && !fileio::resolveOutputTarget(o.png, pngError)) throw CliError(pngError);

  house::HouseMapper mapper(site, config);
  const sim::World& world = mapper.world();
  // The plan's room boxes are cells of its raster: they move onto the robot's grid when that grid has the
  // raster's cells and is square to it (the robot set down square on a cell centre). Otherwise labels and
  // coverage place their boxes in metres on the grid the run ended with (planCoverageOnGrid).
  const bool planOnGrid = plan && house::movePlanOntoGrid(*plan, mapper.world(), mapper.robot().frame());
  if (plan && !planOnGrid) {
    std::cout << "(the plan's rooms are on its own " << plan->world.resolutionM() * 100.0
              << " cm grid, not the robot's: they are placed on it by their boxes in metres)\n";
  }
  std::ostringstream traceText;
  std::optional<house::HouseTrace> trace;
  if (!o.trace.empty()) {
    trace.emplace(traceText);
    mapper.setTrace(&*trace);
  }
  mapper.run();
  if (plan) house::labelRoomsFromPlan(mapper, *plan, !planOnGrid);
  const house::HouseScore s = house::scoreHouse(mapper);
  const house::BestFramesScore best = house::scoreWithBestFrames(house::houseInWorld(mapper));
  const house::HouseCounters& c = mapper.counters();
  const auto num = [](double v) { return report::formatNumber(v, 1); };
  std::ostringstream out;
  out << "house            " << (plan ? plan->id : world.name()) << " " << world.width() << "x" << world.height()
      << ", robot " << robot.name << " (" << robot.cellCm << " cm cells), start " << mapper.config().startCol << ","
      << mapper.config().startRow << " heading " << o.heading << ", strategy " << mapping::strategyName(config.strategy)
      << ", noise " << config.noise.name << ", seed " << config.seed
      << (config.grid.isBrick() ? std::string() : ", grid " + config.grid.describe()) << "\n";
  for (const network::RoomNode& r : mapper.network().rooms()) {
    out << "  " << r.name << "  " << r.map.width() << "x" << r.map.height() << " cells, "
        << r.map.count(CellState::Free) << " free, origin at house cell " << r.toHouse.x() << "," << r.toHouse.y()
        << ", turned " << 90 * r.toHouse.quarterTurns() << " deg\n";
  }
  for (const network::Gateway& g : mapper.network().gateways()) {
    const auto& rooms = mapper.network().rooms();
    out << "  gateway " << rooms[static_cast<size_t>(g.roomA)].name << " <-> "
        << rooms[static_cast<size_t>(g.roomB)].name << ", " << g.cellsA.size() << " cells\n";
  }
  out << "rooms            " << s.rooms;
  if (plan) {
    const house::PlanCoverage pc =
        planOnGrid ? house::planCoverage(mapper, *plan) : house::planCoverageOnGrid(mapper, *plan);
    out << " (plan: " << plan->roomNum << " rooms; " << pc.covered << " of " << pc.reachable
        << " reachable plan rooms mapped to >= 90 %)";
  }
  out << "\ngateways         " << s.gateways << " (exits found " << mapper.exitsFound() << ", not passed "
      << mapper.exitsUnreached() << ", openings onto unmapped space explored " << mapper.openingsTried() << ")\n"
      << "agreement        " << num(s.agreementPct()) << " % of " << s.observable << " observable cells (unknown "
      << s.unknown << ", wrong " << s.wrong << " of which " << s.wallsOnFloor
      << " occupied on open floor; wrong elsewhere " << s.wrongElsewhere << ")\n"
      << "best frames      " << num(best.score.agreementPct()) << " % with each room at its best whole-cell frame "
      << "(within 2 cells: the maps apart from their joining; the frames cost "
      << num(best.score.agreementPct() - s.agreementPct()) << " points)\n"
      << "time units       " << num(c.timeUnits()) << " (between rooms: " << c.travel.cellsMoved << " cells; "
      << "relocalisations " << mapper.relocalisations() << ")\n"
      << "sensor requests  " << c.sensorRequests() << "\n"
      << "raw samples      " << c.explore.rawSamples + c.travel.rawSamples << "\n";
  const house::HouseMapper::StartCalibration& cal = mapper.startCalibration();
  if (cal.turns > 0)
    out << "calibrated       first room: "
        << turnCalibrationText(cal.found, cal.errorPpm, cal.turns, config.calibrateTurns == 0, cal.turnedBack) << "\n";
  out << "wheels learnt    " << wheelsLearntText(mapper.wheels(), mapper.robot().wheels()) << "\n";
  std::cout << out.str() << std::flush;
  if (!o.save.empty()) {
    std::string error;
    if (!network::saveHouse(mapper.network(), world.resolutionM(), o.save, error)) throw CliError(error);
    std::cout << "saved            " << o.save << " (" << mapper.network().rooms().size() << " room maps + "
              << network::kHouseFileName << ")\n";
  }
  if (trace) {
    std::string error;
    if (!fileio::writeFileAtomically(o.trace, traceText.str(), error)) throw CliError(error);
    std::cout << traceLine(*trace, o.trace) << "\n";
  }
  if (!o.png.empty()) {
    std::string error;
    if (!report::writePng(o.png, housePicture(mapper), error)) throw CliError(error);
    std::cout << "wrote            " << o.png << "\n";
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
