// Scenario test: the 18 published runs (worlds/seed-appendix-a), both strategies, no noise.
// Acceptance of the foundation: 100 % of the occupied cells a reachable cell can see are
// detected, no cell is marked wrongly, only unobservable cells stay unknown.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "host/mapping/MapScore.hpp"

namespace nxtmap {
namespace {

TEST(AppendixA, BothStrategiesMapEveryObservableCellWithoutNoise) {
  const std::string dir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/";
  std::ifstream tsv(dir + "scenarios.tsv");
  ASSERT_TRUE(tsv.good());
  std::string line;
  int runs = 0;
  while (std::getline(tsv, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string id, map;
    int col = 0, row = 0;
    in >> id >> map >> col >> row;
    const sim::WorldLoad load = sim::World::load(dir + map);
    ASSERT_TRUE(load.world) << load.error;
    for (const mapping::Strategy s : {mapping::Strategy::Propagation, mapping::Strategy::Frontier}) {
      mapping::RunConfig c;
      c.startCol = col;
      c.startRow = row;
      c.noise = *sim::noiseProfileByName("none");
      c.strategy = s;
      mapping::MappingRun run(*load.world, c);
      run.runToEnd();
      const mapping::MapScore score = mapping::scoreRun(run);
      const std::string what = id + " " + mapping::strategyName(s);
      EXPECT_EQ(run.explorer().end(), ExplorerEnd::Complete) << what;
      EXPECT_EQ(score.detectedOccupied, score.observableOccupied) << what;
      EXPECT_EQ(score.wrongCells, 0) << what;
      EXPECT_EQ(score.unknownObservable, 0) << what;
      EXPECT_EQ(score.unknown, score.actualFree + score.actualOccupied - score.foundFree - score.foundOccupied);
    }
    ++runs;
  }
  EXPECT_EQ(runs, 18);
}

}  // namespace
}  // namespace nxtmap
