#include <gtest/gtest.h>

#include <vector>

#include "firmware/app/EventBeeper.hpp"

namespace nxtmap::fw::test {
namespace {
using Mode = protocol::BrickMode;

// A brick's life as the main loop sees it after each pass (mode, ModeMachine::finishes()), and the
// tone each pass plays (hz 0: none): one beep per event, none while nothing changes.
TEST(EventBeeper, OneShortToneForEachOfTheBricksOwnEvents) {
  struct Step {
    const char* what;
    Mode mode;
    uint8_t finishes;
    uint16_t hz, ms;
  };
  const std::vector<Step> steps{
      {"idle at power-on", Mode::Idle, 0, 0, 0},
      {"exploring", Mode::Exploring, 0, 0, 0},
      {"still exploring", Mode::Exploring, 0, 0, 0},
      {"the room's run ends", Mode::Done, 1, 1760, 150},
      {"done, nothing new", Mode::Done, 1, 0, 0},
      {"following a path", Mode::Following, 1, 0, 0},
      {"the path's goal reached", Mode::Idle, 2, 880, 100},
      {"stopped by the PC (no finish)", Mode::Following, 2, 0, 0},
      {"idle after the stop", Mode::Idle, 2, 0, 0},
      {"exploring again", Mode::Exploring, 2, 0, 0},
      {"the motor safety trips", Mode::Fault, 2, 220, 300},
      {"still in fault", Mode::Fault, 2, 0, 0},
      {"the run ends", Mode::Done, 3, 1760, 150},
      {"a house step ends with nothing to say", Mode::Exploring, 4, 0, 0},
      {"wrap-around of the counter", Mode::Idle, 0, 880, 100},
  };
  EventBeeper beeper;
  for (const Step& s : steps) {
    const Beep b = beeper.update(s.mode, s.finishes);
    EXPECT_EQ(b.hz, s.hz) << s.what;
    EXPECT_EQ(b.ms, s.ms) << s.what;
  }
}

// Every tone is one the Speaker plays as asked: 220..14080 Hz, at least 10 ms, short (under 0.5 s).
TEST(EventBeeper, TonesStayWithinTheSpeakersRange) {
  for (const Beep& b : {EventBeeper::kRunEnded, EventBeeper::kGoalReached, EventBeeper::kFault}) {
    EXPECT_GE(b.hz, 220u);
    EXPECT_LE(b.hz, 14080u);
    EXPECT_GE(b.ms, 10u);
    EXPECT_LT(b.ms, 500u);
  }
}

}  // namespace
}  // namespace nxtmap::fw::test
