// SiteFiles: the worlds every simulating command takes (sim, experiments, sim-house, connect sim:, emulate),
// loaded from any format, and the options that place a robot in them: --robot, --noise, --start-jitter.
// Every failure throws CliError with one line naming the file or option and the problem.
#pragma once

#include "host/mapping/ExplorerBuffer.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/Site.hpp"

#include <string>

namespace CLI {
class App;
}

namespace nxtmap::cli {

// By extension and content: .map Moving AI (its cells are the robot's cells, cellCm a side); .yaml/.yml an
// nxtmap world file (top-level `nxtmap_world`) or a ROS map_server map (any resolution it allows: traced at
// its own cells); .json a HouseExpo plan (its outline exactly as given).
sim::Site loadSiteFile(const std::string& path, int cellCm);

// The robot description by name (published, brick).
sim::RobotDescription parseRobot(const std::string& text);
// 0 .. 45 degrees.
double checkStartJitter(double jitterDeg);
// --square for `robot`: auto (yes for the brick, no for the published robot, whose runs reproduce the
// paper's), yes or no; anything else throws CliError.
bool squareAtStart(const std::string& square, const sim::RobotDescription& robot);

// The robot a firmware image is built for: nxtmap-sim.elf the published set-up, any other the brick.
std::string robotForFirmware(const std::string& firmwarePath);

// The nominal start: `start` "COL,ROW" is a cell of a raster world (with `heading` N/E/S/W); for a world
// file, "X,Y" or "X,Y,YAW" in its metres (yaw degrees counter-clockwise from +x, default 90 = facing +y),
// or empty for the file's own start. `where` prefixes messages (a scenario line).
sim::StartPose parseSiteStart(const sim::Site& site, const std::string& start, const std::string& heading,
                              const std::string& where = "");
// The start must lie in free space and the robot's body fit there.
void checkStartFits(const sim::Site& site, const sim::RobotDescription& robot, const sim::StartPose& start,
                    const std::string& where = "");

// The options every simulating command shares, with their defaults.
struct WorldRunOptions {
  std::string noise = "ideal";  // a preset name, or "list" to print the presets and exit
  std::string robot = "published";
  double startJitterDeg = 0.0;
  std::string square = "auto";
  std::string calibrate = "auto";  // --calibrate (sim, experiments): see calibrationOf
  double rangeM = 0.0;      // --range-m (addRangeOption), when rangeGiven
  bool rangeGiven = false;  // otherwise the robot's own trusted range
  std::string grid = "64";  // --grid (addGridOption): room grid cells per side, 64 the brick's
};
// robotNote: what an unset --robot means (default: "default published").
void addWorldRunOptions(CLI::App& command, WorldRunOptions& o, const std::string& robotNote = "default published");
// --square (sim, experiments): the start's wall sweep, see squareAtStart.
void addSquareOption(CLI::App& command, WorldRunOptions& o, bool calibrate = true);  // --square [, --calibrate]
// The start's turn calibration (--calibrate, with --square): `turns` whole turns asked for (yes: 4), or none and,
// whenUnknown, one unasked by a robot that knows its turns no better than an uncalibrated one (auto, as the brick
// does: PilotConfig::calibrateUnknownTurns); no: never. Throws CliError for anything else, or yes with --square no.
struct CalibrationChoice {
  int turns = 0;
  bool whenUnknown = true;
};
CalibrationChoice calibrationOf(const WorldRunOptions& o);
// --range-m (sim, sim-house): the trusted maximum range, overriding the robot's.
void addRangeOption(CLI::App& command, WorldRunOptions& o);
// --grid (sim, experiments, connect sim:): the room grid the explorer maps into, cells per side.
void addGridOption(CLI::App& command, WorldRunOptions& o);
// The grid asked for: 16, 32, 64 (the brick's) or 128 cells per side; anything else throws CliError.
mapping::GridCapacity gridOf(const WorldRunOptions& o);
// The line for a run that ended GridFull: the room is larger than `grid` at cells of cellCm, mapped up to the
// grid's edge; names the --grid that holds a room of roomCols x roomRows cells whole (if any does).
std::string gridFullNote(const mapping::GridCapacity& grid, int cellCm, int roomCols, int roomRows);

// The robot asked for (--robot), with its range overridden by --range-m; the range is checked against its cells.
sim::RobotDescription robotOf(const WorldRunOptions& o);
// --noise list: prints every preset's values with units; true when it did (the command then exits 0).
bool printNoiseListIfAsked(const WorldRunOptions& o);
// A positional argument left optional for CLI11 (so `--noise list` needs none) but required otherwise:
// "what is required" (e.g. "sim: world").
void requirePositional(const std::string& value, const std::string& what);

}  // namespace nxtmap::cli
