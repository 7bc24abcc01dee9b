// `explore house` plans with the connected brick's own sensor geometry, as its HelloReply told it:
// the stand-in brick simulating the NXT robot (20 cm cells, 7 cm .. 1.2 m, sensors 6 cm ahead) or
// the published one (10 cm cells, 5 cm .. 1 m, centred); before the brick answered, it is refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/console/ConsoleCommand.hpp"
#include "host/console/HouseExploration.hpp"
#include "host/link/LinkHarness.hpp"
#include "host/sim/RobotDescription.hpp"

namespace nxtmap::console {
namespace {

// A small room of `cellM` cells; the robot starts at (2, 2).
sim::World room(double cellM) {
  return sim::World::fromRows(
      {"##########", "#........#", "#........#", "#...##...#", "#........#", "#........#", "##########"}, cellM);
}

struct Case {
  const char* what;
  const char* robot;  // "" = the published point robot
  double cellM;
  int16_t cellCm, minCm, maxCm, mountCm;
};

TEST(HouseExplorationGeometry, PlansWithTheGeometryTheBrickSaidInItsHelloReply) {
  const Case cases[] = {
      {"the stand-in brick as the NXT robot", "brick", 0.20, 20, 7, 120, 6},
      {"the stand-in brick as the published robot", "", 0.10, 10, 5, 100, 0},
  };
  for (const Case& c : cases) {
    link::SimBrickConfig bc;
    bc.run.startCol = 2;
    bc.run.startRow = 2;
    if (*c.robot != '\0') bc.run.robot = sim::robotByName(c.robot);
    link::SimBrick brick(room(c.cellM), bc);
    link::Session pc(link::SessionConfig{0x6E0u, 250, 250});
    link::LinkHarness h(brick, pc, link::HarnessConfig{});
    ASSERT_TRUE(h.runUntil([&] { return pc.connected() && pc.status().has_value(); }, 30000)) << c.what;
    HouseExploration x;
    x.start(pc, 0.0);
    const RangeGeometry& g = x.geometry();
    EXPECT_EQ(g.cellCm, c.cellCm) << c.what;
    EXPECT_EQ(g.minCm, c.minCm) << c.what;
    EXPECT_EQ(g.maxCm, c.maxCm) << c.what;
    EXPECT_EQ(g.mountCm, c.mountCm) << c.what;
    const RangeGeometry& own = brick.explorerConfig().geometry;  // everything, the sure-hit limit too
    EXPECT_EQ(g.cellCm, own.cellCm) << c.what;
    EXPECT_EQ(g.sureCm, own.sureCm) << c.what;
  }
}

TEST(HouseExplorationGeometry, IsRefusedBeforeTheBrickAnswered) {
  link::Session pc(link::SessionConfig{0x6E1u, 250, 250});
  HouseExploration x;
  try {
    x.start(pc, 0.0);
    FAIL() << "started without a HelloReply";
  } catch (const ConsoleError& e) {
    EXPECT_NE(std::string(e.what()).find("the brick has not answered yet"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(x.active());
}

}  // namespace
}  // namespace nxtmap::console
