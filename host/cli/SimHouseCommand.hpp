// `nxtmap sim-house WORLD [--start C,R] [--noise P] [--seed N] [--save DIR] [--trace FILE.csv] [--png FILE.png]`:
// maps a house in the simulator room by room (host/house/HouseMapper), prints the rooms, gateways, counters and the
// merged map's agreement with the world, and optionally saves the house (one ROS map per room and a house file),
// the run's trace and a picture of the merged map on the world (wrong cells marked).
#pragma once
#include <optional>
#include <string>

#include "host/cli/SiteFiles.hpp"

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct SimHouseOptions {
  std::string world;  // HouseExpo .json, Moving AI .map or ROS .yaml
  std::string start;  // COL,ROW; optional for a HouseExpo plan (a start is picked)
  std::string heading = "N";
  WorldRunOptions run;  // --noise, --robot, --start-jitter, --range-m
  std::string seed = "1";
  std::string strategy = "frontier";
  std::string save;   // directory to write the house to
  std::string trace;  // CSV of every action's belief and truth (house/HouseTrace)
  std::string png;    // picture of the merged map on the world's raster (report/MapImage)
};

CLI::App* addSimHouseCommand(CLI::App& app, SimHouseOptions& options);
int runSimHouse(const SimHouseOptions& options);

}  // namespace nxtmap::cli
