#include "host/mapping/SimDrive.hpp"

#include <gtest/gtest.h>

#include "host/sim/NoiseProfile.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::mapping {
namespace {

const sim::World& hall() {
  static const sim::World w = sim::World::fromRows({"#######", "#.....#", "#.....#", "#.....#", "#######"});
  return w;
}

// A rotation is heard as the brick's drive layer reports it (firmware ActionRunner: the encoders' counts over
// the nominal geometry): with 56 mm wheels on a 112 mm track a motor degree turns the robot 8.73 mrad, so a turn
// is carried out and heard in whole counts. Told 85 mrad (a sweep's 87 through a +2 % turn error): 10 counts,
// 87 mrad heard; heard as told, the pilot lost 2 mrad a step, 70 over a sweep.
TEST(SimDrive, ARotationIsHeardAsTheEncodersCountIt) {
  const struct {
    int32_t told, heard;
  } table[] = {{87, 87}, {85, 87}, {80, 79}, {-150, -148}, {1571, 1571}, {-1540, -1536}, {3, 0}};
  RangeGeometry geometry;
  for (const auto& t : table) {
    sim::SimRobot robot(hall(), 3, 2, sim::Heading::N, *sim::noiseProfileByName("nxt"), 1);
    const DriveEvent e = carryOutOnRobot(robot, DriveAction::rotate(t.told), geometry);
    ASSERT_EQ(e.kind, DriveEvent::Kind::Rotated) << t.told;
    EXPECT_TRUE(e.measured) << t.told;
    EXPECT_EQ(e.achieved, t.heard) << t.told;
  }
}

// Wheels without encoders (the published `typical` model) carry a turn out as told, and it is heard so.
TEST(SimDrive, WithoutEncodersARotationIsHeardAsTold) {
  RangeGeometry geometry;
  sim::SimRobot robot(hall(), 3, 2, sim::Heading::N, *sim::noiseProfileByName("typical"), 1);
  const DriveEvent e = carryOutOnRobot(robot, DriveAction::rotate(85), geometry);
  ASSERT_EQ(e.kind, DriveEvent::Kind::Rotated);
  EXPECT_FALSE(e.measured);
}

}  // namespace
}  // namespace nxtmap::mapping
