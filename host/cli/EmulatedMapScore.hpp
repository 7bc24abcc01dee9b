// EmulatedMapScore: the emulated brick's map, as a PC keeps it from the radio (link::MirrorMap), scored
// against the world as a simulated run's map is (mapping::scoreMap: detected, wrong, unsafe free, lost, and
// the same after the best rigid alignment), so `nxtmap emulate --score` and the benchmark put the firmware's
// figures beside the host's on the same room and seed.
// The grid it is scored on is laid as the simulator lays it once the start's sweep is over
// (mapping::SquaredGrid): turned to the walls' axis nearest to where the robot faced when its explorer began
// (the radio's first map cells), its start cell's centre where the brick believed it then: the robot's centre less
// the offset the first Status of the explorer told (ExplorerStart).
#pragma once

#include <string>

#include "host/cli/RadioMirror.hpp"
#include "host/emu/Brick.hpp"
#include "host/mapping/MapScore.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::cli {

// The brick's map and believed cell as `radio` kept them (its explorer's frame; no Status counts as lost), laid on
// the grid laid at the radio's explorer start: the truth rasterised on that grid, and what the score reads
// (input.truth is set when it is scored). `sonar`: the noise profile the robot ran under (its trusted range
// decides which cells a reading can prove).
struct EmulatedMap {
  sim::World truth;
  mapping::ScoreInput input;
  sim::Heading heading = sim::Heading::N;  // the heading the brick's last Status told, on the grid
};
EmulatedMap layEmulatedMap(const emu::Brick& brick, const RadioMirror& radio, const sim::SonarNoise& sonar);

// The map scored against the truth.
mapping::MapScore scoreEmulatedMap(const EmulatedMap& map);

// The map's picture against the truth (report::renderMapImage's colours), written whole to `path` or not at all;
// false with `error` set.
bool writeEmulatedMapPng(const std::string& path, const EmulatedMap& map, std::string& error);

// The score as `nxtmap emulate --score` prints it: detected, wrong cells, aligned, lost; one line each.
std::string scoreLines(const mapping::MapScore& m);

}  // namespace nxtmap::cli
