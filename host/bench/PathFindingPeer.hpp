// PathFindingPeer: PathFinding.js (npm `pathfinding`: AStarFinder, OnlyWhenNoObstacles, octile), the peer the
// path-search bench times our planners against, installed locally with npm (scripts/peer/package.json) and run
// with node (scripts/peer/pathfinding-peer.js) on a sample of a Moving AI scenario's problems.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "host/plan/MovingAiScenario.hpp"

namespace nxtmap::bench {

// Installs the peer into peerDir (npm, locally) when missing. Returns "" when ready, else why not.
std::string preparePeer(const std::filesystem::path& peerDir);

struct PeerRun {
  std::vector<double> micros;   // per sample problem: findPath alone, microseconds
  std::vector<double> lengths;  // per sample problem: the path's length (-1: no path)
  std::string error;            // "" when the peer answered every problem
};

// The peer on problems[i] for every i in `sample`, on `map` (a Moving AI .map).
PeerRun runPeer(const std::filesystem::path& peerDir, const std::filesystem::path& map,
                const std::vector<plan::ScenarioProblem>& problems, const std::vector<size_t>& sample);

}  // namespace nxtmap::bench
