// `nxtmap sim WORLD [--start C,R] ...`: one mapping run in the simulator, shown live or at the end,
// then its counters and its score against the world.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "host/cli/SiteFiles.hpp"

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct SimOptions {
  std::string world;
  std::string start;
  std::string heading = "N";
  WorldRunOptions run;  // --noise, --robot, --start-jitter, --range-m, --grid
  std::string seed = "1";
  std::string strategy = "propagation";
  std::string show = "final";  // live | final | none
  int delayMs = 30;            // live frame delay
  std::string png;             // optional PNG of the final map
  std::string save;            // optional ROS map_server YAML (+PGM) of the explored map, world frame
  std::string trace;           // optional CSV of the believed and true pose after every action (mapping::RunTrace)
  std::string wheels;          // optional wheels file (WheelFile): read at the start if it exists, written at the end
};

// Registers the subcommand; the options are filled in by CLI11.
CLI::App* addSimCommand(CLI::App& app, SimOptions& options);

// Runs it; throws CliError on bad input. Returns the exit code.
int runSim(const SimOptions& options);

}  // namespace nxtmap::cli
