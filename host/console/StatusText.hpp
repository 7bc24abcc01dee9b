// StatusText: what the console prints of the brick's state: `status` (the link, the robot's mode, cell and
// offset, the map, both ends' counters, the goal), the wheels' turn error as the brick reports it, what a
// `calibrate` measured and what `battery` heard. Texts only: the Console asks the link and waits.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "host/console/GoalDriver.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::console {

// `status`: one line each for the link, the robot (once a Status came), the map, the brick's counters (once
// reported), the PC's counters and the goal (when there is one).
std::string statusText(const link::Session& s, const std::string& linkText, const GoalDriver& goals);

// The console's one-line state: the link's state, the robot's mode, the map's known cells and the goal's route.
std::string statusLineText(const std::string& linkState, const link::Session& s, const GoalDriver& goals);

// The turn error the brick's Counters report, "+1.91 %".
std::string turnErrorText(const protocol::CountersMsg& k);

// `calibrate`'s answer from the turn error before and after (turnErrorText); the same text twice: not calibrated.
std::string calibrationText(const std::string& before, const std::string& after);

// `battery`'s answer: the brick's own reading and LEGO's GET_BATTERY_LEVEL, mV, either missing.
std::string batteryText(const std::optional<uint16_t>& millivolts, const std::optional<uint16_t>& legoMillivolts);

}  // namespace nxtmap::console
