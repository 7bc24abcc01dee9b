// The PC's Session queues only commands the brick's own decoder takes: the brick acknowledges a
// malformed command and never runs it, so one sent would be a command lost without a word. Each
// refused command throws std::invalid_argument and takes no sequence number; the next good one
// follows the last good one.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/protocol/HouseMessages.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::link {
namespace {

using namespace protocol;

// A doorway 4 cells wide along x at y 5, crossed northward from (11, 4).
EnterRoomMsg goodEntry() {
  EnterRoomMsg m;
  m.roomId = 2;
  m.door.first = Cell{10, 5};
  m.door.width = 4;
  m.door.alongX = true;
  m.outward = Dir::North;
  m.inside = Cell{11, 4};
  return m;
}

TEST(SessionCommandCheck, CommandsTheBrickWouldRefuseAreNotQueued) {
  struct Case {
    const char* what;
    std::function<void(Session&)> send;
  };
  const auto entry = [](const std::function<void(EnterRoomMsg&)>& change) {
    return [change](Session& s) {
      EnterRoomMsg m = goodEntry();
      change(m);
      s.enterRoom(m);
    };
  };
  const std::vector<Case> cases = {
      {"a doorway 33 cells wide (at most 32)", entry([](EnterRoomMsg& m) { m.door.width = 33; })},
      {"a doorway 9 cells deep (at most 8)", entry([](EnterRoomMsg& m) { m.door.depth = 9; })},
      {"an inside cell one step short of the doorway", entry([](EnterRoomMsg& m) { m.inside = Cell{11, 3}; })},
      {"an inside cell beside the doorway", entry([](EnterRoomMsg& m) { m.inside = Cell{14, 4}; })},
      {"crossing along the doorway", entry([](EnterRoomMsg& m) { m.outward = Dir::East; })},
      {"a goal off the wire's coordinates", [](Session& s) { s.goTo(1, Cell{20000, 0}); }},
      {"a pose off the wire's coordinates", [](Session& s) { s.setPose(Pose{Cell{0, -20000}, Dir::North}); }},
      {"scan id 0", [](Session& s) { s.scan(0); }},
  };
  Session pc{SessionConfig{7, 250, 250}};
  uint16_t last = pc.enterRoom(goodEntry());
  for (const Case& c : cases) {
    EXPECT_THROW(c.send(pc), std::invalid_argument) << c.what;
    const uint16_t next = pc.scan(1);
    EXPECT_EQ(next, static_cast<uint16_t>(last + 1)) << c.what << ": a refused command took a sequence number";
    last = next;
  }
}

TEST(SessionCommandCheck, TheWidestAndDeepestDoorwayGoesOut) {
  Session pc{SessionConfig{7, 250, 250}};
  EnterRoomMsg m = goodEntry();
  m.door.width = kMaxDoorwayWidth;
  m.door.depth = kMaxDoorwayDepth;
  m.inside = Cell{20, 4};
  EXPECT_NO_THROW(pc.enterRoom(m));
  m.door.alongX = false;  // the same doorway across x, crossed eastward from its west side
  m.outward = Dir::East;
  m.inside = Cell{9, 12};
  EXPECT_NO_THROW(pc.enterRoom(m));
}

}  // namespace
}  // namespace nxtmap::link
