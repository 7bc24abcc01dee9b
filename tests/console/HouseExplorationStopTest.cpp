// `explore house` when the brick can no longer carry the console's order out: its motor safety
// tripped (Fault), or the order was ended on the brick (a button, another console's command) and it
// stands still without reporting it. The house stops with one clear reason instead of waiting for
// ever; a brick that reports late, or a link that is down, does not stop it. The brick's side is
// played packet by packet: a HelloReply, the acknowledgement of each command, then Status packets.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "tests/console/HouseByPacket.hpp"

namespace nxtmap::console {
namespace {

using protocol::BrickMode;
using HouseStopTest = test::HouseByPacket;

TEST_F(HouseStopTest, AMotorFaultStopsTheHouseAtOnceWithItsReason) {
  ASSERT_TRUE(house.active());
  status(BrickMode::Fault, 5.0);
  EXPECT_FALSE(house.active());
  EXPECT_FALSE(house.done());
  EXPECT_NE(house.stopped().find("stopped its motors"), std::string::npos) << house.stopped();
  EXPECT_NE(said.find("house stopped: "), std::string::npos) << said;
}

// The brick standing still (Idle) while the first room is awaited: how long, over how many statuses,
// and whether it stops.
struct StillRow {
  const char* what;
  int statuses;
  double seconds;
  bool stops;
};

void PrintTo(const StillRow& r, std::ostream* os) { *os << r.what; }

class HouseStillTest : public HouseStopTest, public ::testing::WithParamInterface<StillRow> {};

TEST_P(HouseStillTest, AnOrderDroppedOnTheBrickStopsTheHouseAfterAMinuteOfStatuses) {
  const StillRow& r = GetParam();
  statuses(BrickMode::Idle, r.statuses, 10.0, 10.0 + r.seconds);
  EXPECT_EQ(!house.stopped().empty(), r.stops) << r.what << ": " << said;
  EXPECT_EQ(house.active(), !r.stops) << r.what;
  if (r.stops) {
    EXPECT_NE(house.stopped().find("stands still"), std::string::npos) << house.stopped();
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, HouseStillTest,
                         ::testing::Values(StillRow{"a minute of statuses (two a second), all idle", 121, 60.0, true},
                                           StillRow{"idle for 50 s: a late report may still come", 101, 50.0, false},
                                           StillRow{"80 s but only 60 statuses: the link was mostly down", 60, 80.0,
                                                    false},
                                           StillRow{"five minutes idle", 601, 300.0, true}));

TEST_F(HouseStopTest, MovingAgainStartsTheMinuteAfresh) {
  statuses(BrickMode::Idle, 900, 10.0, 55.0);
  status(BrickMode::Exploring, 56.0);
  statuses(BrickMode::Idle, 900, 57.0, 102.0);
  EXPECT_TRUE(house.active()) << said;
  EXPECT_TRUE(house.stopped().empty());
  statuses(BrickMode::Idle, 400, 103.0, 123.0);
  EXPECT_FALSE(house.active());
}

TEST_F(HouseStopTest, AStopFromThisConsoleIsNotReportedAsAFailure) {
  house.cancel();
  status(BrickMode::Fault, 5.0);
  EXPECT_FALSE(house.active());
  EXPECT_TRUE(house.stopped().empty());
}

}  // namespace
}  // namespace nxtmap::console
