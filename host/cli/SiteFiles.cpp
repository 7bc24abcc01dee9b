#include "host/cli/SiteFiles.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/sim/StartJitter.hpp"
#include "host/worlds/SiteFiles.hpp"

namespace nxtmap::cli {

sim::Site loadSiteFile(const std::string& path, int cellCm) {
  worlds::SiteLoad load = worlds::loadSite(path, cellCm);
  if (!load.site) throw CliError(load.error);
  return std::move(*load.site);
}

sim::RobotDescription parseRobot(const std::string& text) {
  if (const auto r = sim::robotByName(text)) return *r;
  throw CliError("--robot must be one of " + joinNames(sim::robotNames()) + ", not '" + text + "'");
}

double checkStartJitter(double jitterDeg) {
  if (const std::string why = sim::startJitterProblem(jitterDeg); !why.empty()) throw CliError(why);
  return jitterDeg;
}

bool squareAtStart(const std::string& square, const sim::RobotDescription& robot) {
  if (square == "yes") return true;
  if (square == "no") return false;
  if (square == "auto") return robot.name == "brick";
  throw CliError("--square must be auto, yes or no, not '" + square + "'");
}

CalibrationChoice calibrationOf(const WorldRunOptions& o) {
  CalibrationChoice c;
  if (o.calibrate == "auto") return c;
  if (o.calibrate == "no") {
    c.whenUnknown = false;
    return c;
  }
  if (o.calibrate != "yes") throw CliError("--calibrate must be auto, yes or no, not '" + o.calibrate + "'");
  if (o.square == "no") throw CliError("--calibrate measures against the walls: it needs --square yes or auto");
  c.turns = 4;
  return c;
}

namespace {

// "X,Y" or "X,Y,YAW": finite numbers in metres and degrees.
bool parseMetres(const std::string& text, double out[3], int& count) {
  count = 0;
  size_t pos = 0;
  while (pos <= text.size() && count < 3) {
    const size_t comma = text.find(',', pos);
    const std::string part = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || end == part.c_str() || !std::isfinite(v) ||
        std::any_of(static_cast<const char*>(end), part.c_str() + part.size(), [](char c) { return c != ' '; }))
      return false;
    out[count++] = v;
    if (comma == std::string::npos) return count >= 2;
    pos = comma + 1;
  }
  return false;
}

}  // namespace

sim::StartPose parseSiteStart(const sim::Site& site, const std::string& start, const std::string& heading,
                              const std::string& where) {
  if (site.raster && !start.empty()) {
    const CellArg cell = parseCell(start, "--start");
    checkStart(*site.raster, cell.col, cell.row, where);
    return site.rasterStart(cell.col, cell.row, sim::headingToDeg(parseHeading(heading)));
  }
  if (start.empty()) {
    if (site.start) return *site.start;
    throw CliError(where + "--start is needed: " + site.name + " gives no start of its own");
  }
  double v[3] = {0.0, 0.0, 90.0};
  int count = 0;
  if (!parseMetres(start, v, count) || std::fabs(v[0]) > 1000.0 || std::fabs(v[1]) > 1000.0)
    throw CliError(where +
                   "--start must be X,Y or X,Y,YAW in the world file's metres and degrees (|X|, |Y| <= 1000), not '" +
                   start + "'");
  return sim::StartPose{sim::Vec2(v[0] * 100.0, -v[1] * 100.0), 90.0 - v[2]};
}

void checkStartFits(const sim::Site& site, const sim::RobotDescription& robot, const sim::StartPose& start,
                    const std::string& where) {
  char at[96];
  std::snprintf(at, sizeof at, "start (%.2f, %.2f) m", start.cm.x() / 100.0, -start.cm.y() / 100.0);
  if (site.scene->solidAt(start.cm)) throw CliError(where + site.name + ": " + at + " lies inside an obstacle");
  const auto corners = robot.footprint(start.cm.x(), start.cm.y(), start.headingDeg);
  if (corners.empty()) return;
  std::vector<sim::Vec2> body;
  for (const auto& c : corners) body.emplace_back(c[0], c[1]);
  if (!site.scene->touches(body)) return;
  char size[96];
  std::snprintf(size, sizeof size, "the %s robot's body (%.0f x %.0f cm)", robot.name.c_str(), robot.bodyLengthCm,
                robot.bodyWidthCm);
  throw CliError(where + site.name + ": " + at + ": " + size + " does not fit there");
}

void addWorldRunOptions(CLI::App& command, WorldRunOptions& o, const std::string& robotNote) {
  command.add_option("--noise", o.noise,
                     "sonar and wheel model: " + joinNames(sim::noiseProfileNames()) +
                         " (default ideal); 'list' prints each preset's values");
  command.add_option("--robot", o.robot,
                     "the robot: published (10 cm cells, sensors at the centre, a point) or brick (the NXT as "
                     "built: 20 cm cells, sensors 6 cm out, a 16 x 18 cm body); " +
                         robotNote);
  command.add_option("--start-jitter", o.startJitterDeg,
                     "set the robot down off the start cell's centre and up to DEG degrees off square, drawn per "
                     "seed (0 = square on the centre, the default)");
}

void addSquareOption(CLI::App& command, WorldRunOptions& o, bool calibrate) {
  command.add_option("--square", o.square,
                     "before mapping, sweep the sonars on the spot and turn square to the room's walls: auto (the "
                     "default: the brick does, the published robot does not, as in the paper), yes, no");
  if (!calibrate) return;
  command.add_flag("--calibrate{yes}", o.calibrate,
                   "before mapping, measure how far the robot's turns are off against the walls (two sweeps with "
                   "4 whole turns between them) and correct every turn by it; squares to the walls as well. "
                   "--calibrate=auto (the default) does so when the robot knows its turns no better than an "
                   "uncalibrated NXT (nothing stored), as the brick does; --calibrate=no never");
}

void addRangeOption(CLI::App& command, WorldRunOptions& o) {
  command
      .add_option("--range-m", o.rangeM, "trusted maximum sensor range in metres (default: the robot's, 1 m published)")
      ->each([&o](const std::string&) { o.rangeGiven = true; });
}

void addGridOption(CLI::App& command, WorldRunOptions& o) {
  command.add_option("--grid", o.grid,
                     "room grid of CELLS x CELLS: 16, 32, 64 or 128 (default 64, the brick's own; a larger room is "
                     "mapped up to the grid's edge, as on the brick)");
}

mapping::GridCapacity gridOf(const WorldRunOptions& o) {
  const std::string problem = countProblem(o.grid, 16, 128);
  if (problem.empty()) {
    if (const auto grid = mapping::GridCapacity::ofCells(std::stoi(o.grid))) return *grid;
  }
  throw CliError("--grid must be 16, 32, 64 (the brick's) or 128 cells per side, not '" + o.grid + "'");
}

std::string gridFullNote(const mapping::GridCapacity& grid, int cellCm, int roomCols, int roomRows) {
  const int side = std::max(roomCols, roomRows);
  std::string larger;
  for (int cells = grid.cells * 2; cells <= 128 && larger.empty(); cells *= 2) {
    if (cells >= side) larger = "--grid " + std::to_string(cells) + " maps it whole";
  }
  if (larger.empty()) larger = "no grid of up to 128 cells holds it whole";
  char metres[32];
  std::snprintf(metres, sizeof metres, "%g", grid.cells * cellCm / 100.0);
  const std::string n = std::to_string(grid.cells);
  return "the room is larger than the " + n + " x " + n + "-cell grid (" + metres + " m at " + std::to_string(cellCm) +
         " cm cells): mapped up to its edge; " + larger;
}

sim::RobotDescription robotOf(const WorldRunOptions& o) {
  sim::RobotDescription robot = parseRobot(o.robot);
  if (o.rangeGiven) robot.rangeM = checkRangeM(o.rangeM);
  checkRangeCoversCell(robot.cellCm, robot.rangeM);
  return robot;
}

std::string robotForFirmware(const std::string& firmwarePath) {
  const std::string name = std::filesystem::path(firmwarePath).filename().string();
  return name.find("-sim") != std::string::npos ? "published" : "brick";
}

void requirePositional(const std::string& value, const std::string& what) {
  if (value.empty()) throw CliError(what + " is required");
}

bool printNoiseListIfAsked(const WorldRunOptions& o) {
  if (o.noise != "list") return false;
  std::cout << sim::describeNoiseProfiles() << std::flush;
  return true;
}

}  // namespace nxtmap::cli
