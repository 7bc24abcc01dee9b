// The explorers' travel searches run in slices (Action::think between them) so one step stays
// within the brick's CPU budget. Slicing must not change a single decision.
#include <gtest/gtest.h>

#include <string>

#include "host/mapping/MapScore.hpp"

namespace nxtmap {
namespace {

TEST(Thinking, SlicedSearchesGiveTheSameRunAsWholeOnes) {
  const std::string dir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/";
  const sim::WorldLoad load = sim::World::load(dir + "occupancy-127.map");
  ASSERT_TRUE(load.world) << load.error;
  for (const mapping::Strategy s : {mapping::Strategy::Propagation, mapping::Strategy::Frontier}) {
    mapping::RunConfig c;
    c.startCol = 1;
    c.startRow = 20;
    c.strategy = s;
    c.searchSliceStates = 0xFFFF;
    mapping::MappingRun whole(*load.world, c);
    uint64_t thinksWhole = 0;
    while (!whole.finished()) {
      if (whole.lastAction().kind == DriveAction::Kind::Think) ++thinksWhole;
      whole.step();
    }
    c.searchSliceStates = 4;
    mapping::MappingRun sliced(*load.world, c);
    uint64_t thinksSliced = 0;
    while (!sliced.finished()) {
      if (sliced.lastAction().kind == DriveAction::Kind::Think) ++thinksSliced;
      sliced.step();
    }
    const std::string name = mapping::strategyName(s);
    EXPECT_GT(thinksWhole, 0u) << name;  // one per search: clearing the planner is a slice of its own
    EXPECT_GT(thinksSliced, 2 * thinksWhole) << name;
    EXPECT_EQ(whole.counters().timeHalfUnits(), sliced.counters().timeHalfUnits()) << name;
    EXPECT_EQ(whole.counters().sensorRequests, sliced.counters().sensorRequests) << name;
    for (int row = 0; row < load.world->height(); ++row)
      for (int col = 0; col < load.world->width(); ++col)
        ASSERT_EQ(whole.belief(col, row), sliced.belief(col, row)) << name << " at " << col << "," << row;
  }
}

}  // namespace
}  // namespace nxtmap
