// `nxtmap paths MAP --scen FILE.scen [--algo ...] [--csv FILE]`: every Moving AI problem of a scenario
// file, each checked against its published optimal length (within 1e-3). Exit 0 when all match, 1 otherwise.
#pragma once
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct PathsOptions {
  std::string map;
  std::string scen;
  std::string algo = "astar";
  std::string csv;
  uint64_t maxNodes = 0;  // per problem, 0: no limit
};

CLI::App* addPathsCommand(CLI::App& app, PathsOptions& options);
int runPaths(const PathsOptions& options);

}  // namespace nxtmap::cli
