// RealismRuns: the runs behind the realism section of `make bench` (RealismBench.cpp): a set of worlds
// (rooms or houses) with one robot, run under one variant of the simulated world (noise, schedule, set-down),
// summed into a Tally of the honest scores (mapping::MapScore).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "host/mapping/MapScore.hpp"
#include "host/mapping/Strategy.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/Site.hpp"

namespace nxtmap::bench {

// One start in one world. Sites are owned by the caller and outlive every run.
struct RealismStart {
  const sim::Site* site = nullptr;
  int startCol = 0, startRow = 0;      // a raster cell, heading N (when pose is empty: the published set-up)
  std::optional<sim::StartPose> pose;  // the world file's own start instead
};

// Worlds run alike: rooms (MappingRun) or houses (HouseMapper, room by room).
struct RealismSet {
  std::string name;  // as printed: "published", "brick", "furnished", "houses"
  sim::RobotDescription robot;
  std::vector<RealismStart> starts;
  int seeds = 1;  // seeds 1..seeds per start
  bool houses = false;
};

// What is changed in the world for one row.
struct RealismVariant {
  sim::NoiseProfile noise;
  bool sensorsTogether = false;  // mapping::RunConfig::sensorsTogether (rooms only)
  double misalignDeg = 0.0;      // the start heading turned this far off square: + on odd seeds, - on even
  double offsetCells = 0.0;      // the start moved right and down by this share of the robot's cell
  std::optional<sim::RobotDescription> robot;  // replaces the set's robot
};

// Sums over runs; means and counts for the table.
struct Tally {
  int runs = 0;
  int lost = 0;           // runs whose believed cell at the end is not the true one
  bool lostKnown = true;  // false for houses (HouseMapper keeps its belief to itself)
  double detected = 0.0, worstDetected = 100.0, wrong = 0.0, unsafeFree = 0.0;
  double detectedAligned = 0.0, wrongAligned = 0.0;
  double agreement = 0.0;  // houses: house::scoreHouse's agreement %, summed (the house section's measure)

  void add(const mapping::MapScore& s);
  double mean(double sum) const { return runs == 0 ? 0.0 : sum / runs; }
};

using RealismProgress = std::function<void()>;  // called after every run

// Every start of `set` with seeds 1..set.seeds under `variant` and `strategy`.
Tally runRealism(const RealismSet& set, const RealismVariant& variant, mapping::Strategy strategy,
                 const RealismProgress& progress = {});

// A preset as a variant (square start, the set's robot).
RealismVariant presetVariant(const std::string& preset);

}  // namespace nxtmap::bench
