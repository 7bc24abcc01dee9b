// `nxtmap path MAP --from C,R --to C,R|near:LABEL [--algo seed|astar|jps|jps+|dijkstra]`: one path on a map
// (a world, or a map saved by `nxtmap sim --save`), drawn on the map, with its length and nodes expanded.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct PathOptions {
  std::string map;
  std::string from;
  std::string to;  // "C,R" or "near:LABEL"
  std::string algo = "astar";
  std::vector<std::string> labels;  // extra labels "NAME=C,R" or "NAME=C,R,W,H"
  int clearance = 0;                // cells
  bool throughUnknown = false;
  std::string draw = "auto";  // auto | always | never
  uint64_t maxNodes = 0;      // 0: no limit
  std::string house;          // --house DIR: route across the rooms of a saved house (HousePathCommand)
};

CLI::App* addPathCommand(CLI::App& app, PathOptions& options);
// Throws CliError on bad input (including no path); returns the exit code.
int runPath(const PathOptions& options);

}  // namespace nxtmap::cli
