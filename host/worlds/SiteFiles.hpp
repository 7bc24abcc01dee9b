// SiteFiles: a world file of any format the simulator reads, loaded as a Site. Shared by every command that
// simulates (sim, experiments, sim-house, connect sim:, emulate).
#pragma once

#include "host/sim/Site.hpp"

#include <optional>
#include <string>

namespace nxtmap::worlds {

struct SiteLoad {
  std::optional<sim::Site> site;
  std::string error;  // one line naming the file and the problem when site is empty
};

// By extension and content: .map Moving AI (the format has no resolution: its cells are taken as cellCm, the
// robot's own); .yaml/.yml an nxtmap world file (top-level `nxtmap_world`, sim/WorldFile) or else a ROS
// map_server map (any resolution RosMapFile allows, traced at its own cells); .json a HouseExpo plan (its
// outline exactly as given; its default start). Anything else: "unknown world format".
SiteLoad loadSite(const std::string& path, int cellCm);

}  // namespace nxtmap::worlds
