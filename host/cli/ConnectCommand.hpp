// `nxtmap connect LINK`: the interactive console to a brick over bt:, serial:, tcp: (or the
// in-process stand-in sim:WORLD). Commands come from the terminal (live map redrawn while the
// brick explores) or, when stdin is not a terminal, one per line as a script.
#pragma once
#include <string>

#include "host/cli/SiteFiles.hpp"

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct ConnectOptions {
  std::string link;
  double speed = 1.0;  // sim: only: how much faster than real time the stand-in runs
  double connectTimeoutS = 20;
  bool live = true;        // redraw the map while the brick explores (terminals only)
  std::string house;       // a saved house directory to load (empty: none)
  int room = 0;            // with house: the room the brick stands in (its pose is in that room's frame)
  WorldRunOptions run;     // sim: links: --noise, --robot, --start-jitter, --grid
  std::string seed = "1";  // sim: links: the noise's seed
};

CLI::App* addConnectCommand(CLI::App& app, ConnectOptions& options);
int runConnect(const ConnectOptions& options);

}  // namespace nxtmap::cli
